// The one owner of an open GDAL dataset, and the read-only open every GDAL reader in
// lib/ goes through (rasters in geo, image, radiometry and scene; vector sources in
// scenegen). Thread-safety: opening is; a dataset belongs to one thread at a time.
#pragma once

#include <gdal_priv.h>

#include <string>

namespace sigchain::geo {

// A dataset closed with GDALClose when its owner goes (GDAL's own unique pointer; a
// dataset made with a driver's Create() is owned the same way). Closing reports no
// error: a writer reads its output back (image/gdal_output.*).
using GdalDataset = GDALDatasetUniquePtr;

// Opens `path` read-only after gdal_init(), as GDALOpenEx does with `flags` (GDAL_OF_RASTER,
// GDAL_OF_VECTOR, ... ; GDAL_OF_READONLY is added): null when GDAL cannot, with
// gdal_message() saying why. The side files are not checked: a reader of a user's file
// calls check_sidecars(path) first.
GdalDataset open_dataset(const std::string& path, unsigned flags = GDAL_OF_RASTER);

}  // namespace sigchain::geo
