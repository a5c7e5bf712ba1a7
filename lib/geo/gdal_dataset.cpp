// The read-only open of a GDAL dataset (gdal_dataset.hpp).
#include "geo/gdal_dataset.hpp"

#include "geo/crs.hpp"

namespace sigchain::geo {

GdalDataset open_dataset(const std::string& path, unsigned flags) {
    gdal_init();
    return GdalDataset(GDALDataset::FromHandle(
        GDALOpenEx(path.c_str(), flags | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
}

}  // namespace sigchain::geo
