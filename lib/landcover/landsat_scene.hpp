// The steps that prepare a real Landsat scene for validation and score the chain's
// prediction of it (data/scenes/pennsylvania, marburg): land cover from one date's
// digital numbers (classes(5)), cloud and shadow masks, the terrain and land use on
// one grid with the image, control points, the reflectance fit, the materials' .ems
// curves from published spectra (materials(5)), the scores and the pictures.
// landsat_scene(1) runs one step per call. Thread-safety: free functions; each writes
// only the files it is given.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "landcover/cloud_mask.hpp"

namespace sigchain::landcover {

// Classifies images stacked in order (bands numbered across them) by `rules_path`;
// pixels where `mask_path` (if not empty) is non-zero get the class their neighbours
// have (fill_unclassified); writes the map as a Byte GeoTIFF on the first image's grid
// and each class's fraction to `report`.
void classify_step(const std::string& rules_path, const std::vector<std::string>& images,
                   const std::string& mask_path, const std::string& out_path,
                   std::ostream& report);

// Writes the cloud and shadow mask of `images` (kMaskCloud, kMaskShadow) and its
// fractions to `report`.
void mask_step(const CloudMaskRequest& request, const std::vector<std::string>& images,
               const std::string& out_path, std::ostream& report);

// The terrain on the image's pixel corners and the land use on that grid:
// OUTDIR/terrain.tif holds (rows + 1) x (columns + 1) heights, each the mean of the DEM
// cells (one per image pixel) that touch the corner, so that the DEM block of odb(5)
// whose upper-left vertex is corner (r, c) covers image pixel (r, c) exactly;
// OUTDIR/landuse.tif holds class (r, c) of the image there (the last row and column
// repeat their neighbours and are used by no block). The DEM must be on the class map's
// grid.
void terrain_step(const std::string& dem_path, const std::string& classes_path,
                  const std::string& outdir, std::ostream& report);

struct PointsRequest {
    std::string rules_path;    // class names
    std::string classes_path;  // class map (image grid)
    std::string mask_path;     // "" for none; points avoid non-zero pixels
    int per_class = 30;
    std::uint32_t seed = 1;
    long margin = 4;
    std::string prefix;        // writes PREFIX_fit.cpt and PREFIX_held.cpt
};
void points_step(const PointsRequest& request, std::ostream& report);

// The reflectance scale of each class of the points in `cpt_path` (names CLASS_NN),
// per band of the synthetic images (least squares, fit_reflectance_scale), as
// "NAME s1 ... sN" rows.
void fit_step(const std::string& cpt_path, const std::string& dark_path,
              const std::string& base_path, const std::string& reference_path,
              std::ostream& out);

// Writes OUTDIR/NAME.ems for every material of `materials_path`, scaled per band of
// `snd_path` by `scales_path` ("-": unscaled).
void ems_step(const std::string& materials_path, const std::string& snd_path,
              const std::string& scales_path, const std::string& outdir);

struct ScoreRequest {
    std::string rules_path, synthetic_path, reference_path, classes_path;
    std::vector<std::string> mask_paths;  // pixels non-zero in any are not scored
    std::string points_path;              // "" for none
    int bands = 0;                        // 0: every band both images have
};
void score_step(const ScoreRequest& request, std::ostream& out);

// Pictures: the synthetic image beside the reference (`bands` as red, green, blue),
// each band stretched linearly between the reference's 2nd and 98th percentiles;
// and the difference synthetic - reference of one band as blue (negative) - white -
// red (positive), saturated at +-range counts, masked pixels grey.
void side_by_side_step(const std::string& synthetic_path, const std::string& reference_path,
                       const std::vector<int>& bands, const std::string& out_path);
void difference_step(const std::string& synthetic_path, const std::string& reference_path,
                     int band, double range, const std::vector<std::string>& mask_paths,
                     const std::string& out_path);

// Writes "class_name synthetic reference" rows of one band for every `step`-th clear
// pixel (row-major), for a scatter plot (gnuplot).
void pairs_step(const std::string& rules_path, const std::string& synthetic_path,
                const std::string& reference_path, const std::string& classes_path,
                const std::vector<std::string>& mask_paths, int band, long step,
                std::ostream& out);

// Prints per class of `rules_path` (and "all") and band of `image_path` over the pixels
// with a class and clear of every mask: n, mean, standard deviation, 1st percentile,
// median, 99th percentile ("class band n mean std p01 median p99").
void stats_step(const std::string& rules_path, const std::string& image_path,
                const std::string& classes_path, const std::vector<std::string>& mask_paths,
                std::ostream& out);

// Prints the fraction of clear pixels of each pair (class of map A, class of map B):
// "class_a class_b n fraction_of_a", how one date's land cover reads on another's.
void crosstab_step(const std::string& rules_a, const std::string& classes_a,
                   const std::string& rules_b, const std::string& classes_b,
                   const std::vector<std::string>& mask_paths, std::ostream& out);

}  // namespace sigchain::landcover
