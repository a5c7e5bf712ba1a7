// GDAL set-up shared by every library that reads rasters (image, scene DEMs, texture
// maps), so they all behave alike.
#pragma once

#include <string>

namespace sigchain::image {

// Registers GDAL's drivers once and keeps GDAL quiet (its errors become our messages,
// via gdal_message()) and writes no .aux.xml side files next to inputs or outputs.
// Thread-safe; call before any other GDAL call.
void gdal_init();

// GDAL's last error message on this thread, or "unknown GDAL error".
std::string gdal_message();

}  // namespace sigchain::image
