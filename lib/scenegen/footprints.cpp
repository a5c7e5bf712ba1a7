// Building footprints read with GDAL/OGR into a local metric frame.
#include "scenegen/footprints.hpp"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "geo/crs.hpp"
#include "geo/gdal_dataset.hpp"

namespace sigchain::scenegen {

namespace {

// The errors in this file name the file without a line: a GeoPackage (SQLite) or other
// OGR source has no lines. They name the feature (its fid) where there is one.

Ring outer_ring(const OGRPolygon& polygon, const std::string& path, std::int64_t fid) {
    if (polygon.getNumInteriorRings() > 0)
        throw DataError({path, 0}, "feature " + std::to_string(fid) +
                                       ": expected a polygon without holes, found " +
                                       std::to_string(polygon.getNumInteriorRings()) +
                                       " interior ring(s)");
    const OGRLinearRing* ring = polygon.getExteriorRing();
    Ring out;
    if (ring == nullptr) return out;
    for (int i = 0; i < ring->getNumPoints(); ++i) out.push_back({ring->getX(i), ring->getY(i)});
    return out;
}

void check_crs(const OGRLayer& layer, const std::string& path, std::string& name) {
    const OGRSpatialReference* srs = const_cast<OGRLayer&>(layer).GetSpatialRef();
    if (srs == nullptr || !srs->IsProjected())
        throw DataError({path, 0}, "expected a layer in a projected CRS, found " +
                                       std::string(srs ? "a geographic CRS" : "no CRS"));
    if (std::abs(srs->GetLinearUnits() - 1.0) > 1e-12)
        throw DataError({path, 0}, "expected a projected CRS in metres, found units of " +
                                       std::to_string(srs->GetLinearUnits()) + " m");
    name = srs->GetName() ? srs->GetName() : "";
}

}  // namespace

Footprints read_footprints(const std::string& path) {
    const geo::GdalDataset ds = geo::open_dataset(path, GDAL_OF_VECTOR);
    if (!ds) throw IoError(path + ": " + geo::gdal_message());
    if (ds->GetLayerCount() < 1) throw DataError({path, 0}, "expected a vector layer, found none");
    OGRLayer* layer = ds->GetLayer(0);
    Footprints out;
    check_crs(*layer, path, out.crs_name);
    OGREnvelope env;
    if (layer->GetExtent(&env, TRUE) != OGRERR_NONE)
        throw DataError({path, 0}, "expected a layer with an extent, found none");
    out.origin = {std::round((env.MinX + env.MaxX) / 2), std::round((env.MinY + env.MaxY) / 2)};
    out.extent = {env.MinX - out.origin[0], env.MinY - out.origin[1], env.MaxX - out.origin[0],
                  env.MaxY - out.origin[1]};
    layer->ResetReading();
    for (auto& feature : *layer) {
        const std::int64_t fid = feature->GetFID();
        const OGRGeometry* g = feature->GetGeometryRef();
        if (g == nullptr) continue;
        std::vector<Ring> rings;
        const auto type = wkbFlatten(g->getGeometryType());
        if (type == wkbPolygon) {
            rings.push_back(outer_ring(*g->toPolygon(), path, fid));
        } else if (type == wkbMultiPolygon) {
            for (const auto* p : *g->toMultiPolygon()) rings.push_back(outer_ring(*p, path, fid));
        } else {
            throw DataError({path, 0}, "feature " + std::to_string(fid) +
                                           ": expected a polygon, found " +
                                           OGRGeometryTypeToName(g->getGeometryType()));
        }
        for (auto& ring : rings) {
            for (auto& p : ring) p = {p[0] - out.origin[0], p[1] - out.origin[1]};
            out.buildings.push_back({fid, std::move(ring)});
        }
    }
    return out;
}

}  // namespace sigchain::scenegen
