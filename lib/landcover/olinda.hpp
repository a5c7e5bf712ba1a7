// The Olinda scene's preparation steps (data/scenes/olinda/README.md): land-use
// classification of the Landsat-7 ETM+ image onto the DEM's grid, control points on
// the class map, the least-squares fit of each class's reflectance scale, the classes'
// .ems curves, and the side-by-side preview. olinda_scene(1) runs one step per call.
// Thread-safety: free functions; each writes only the files it is given.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

namespace sigchain::landcover {

inline constexpr int kEtmBands = 4;  // ETM+ bands 1-4 are rendered

// Classifies the ETM+ image (Rule{}), writes OUTDIR/classes_image.tif (the image's
// grid) and OUTDIR/landuse.tif (the DEM's grid, majority per DEM block), and writes to
// `report` each class's fraction on both grids and the image's placement on WGS84.
// Throws IoError or DataError.
void classify_scene(const std::string& etm_path, const std::string& dem_path,
                    const std::string& outdir, std::ostream& report);

struct ControlPointRequest {
    std::string classes_path;  // class map on the image grid (classes_image.tif)
    std::string landuse_path;  // class map on the DEM grid (landuse.tif)
    int per_class = 30;        // points per class, half fit, half held out
    std::uint32_t seed = 0;    // of the pick's pattern (pick_control_points)
    long margin = 6;           // pixels kept clear of the image's edge
    std::string prefix;        // writes PREFIX_fit.cpt and PREFIX_held.cpt
};

// Picks control points where a pixel's class and its DEM block's class agree, writes
// them as two cpt(5) files (the fit half and the held-out half, named CLASS_NN), and
// writes to `report` the number of points of each class.
void write_control_points(const ControlPointRequest& request, std::ostream& report);

// Writes to `out` a table of each class's reflectance scale per band (least squares on
// the points of `cpt_path`), from renders with reflectance 0 (`dark_path`) and with the
// starting reflectances (`base_path`) against the reference image.
void fit_scales(const std::string& cpt_path, const std::string& dark_path,
                const std::string& base_path, const std::string& reference_path, std::ostream& out);

// Writes OUTDIR/CLASS.ems for every class of the reflectance table: emissivity
// 1 - reflectance x scale, flat inside each ETM+ band's half-power edges. `scales_path`
// "-" means every scale is 1. Throws DataError at the table's line for a bad row.
void write_ems_curves(const std::string& reflectance_path, const std::string& scales_path,
                      const std::string& outdir);

// Writes the synthetic counts beside the reference (bands 3, 2, 1 as red, green, blue)
// as an 8-bit image.
void write_preview(const std::string& synthetic_path, const std::string& reference_path,
                   const std::string& out_path);

}  // namespace sigchain::landcover
