// The render's shared types: the options every strategy and stage reads
// (RenderOptions: sampling, bounces, convergence, background, layers), its inputs
// (RenderInputs) and its statistics (RenderStats). Apart from render.hpp so that the
// tracer, its strategies and the stages around the image loop (adjacency, the bounce
// estimate, the Job) include these and not the loop (trace(1), OPTIONS).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "imaging/sensor.hpp"
#include "radiometry/atmosphere.hpp"
#include "radiometry/material.hpp"
#include "scene/scene.hpp"

namespace sigchain::trace {

// The renderer draws its rays from lib/imaging's sensors.
using imaging::Sensor;

// trace --sampling: DIRSIG 3's scheme, the golf ball, Monte Carlo, and White (1996)'s
// proposed model (section 5.2.3: the golf ball at the primary hit, the 10 deg rule for the
// sun at secondary hits).
enum class Sampling { Dirsig, Golfball, MonteCarlo, Proposed };

inline constexpr int kMaxBounces = 64;  // --bounces
inline constexpr int kAutoBounces = -1;  // --bounces auto: the estimate's (bounce_estimate.hpp)

// What rays that leave the scene below the horizon see (world.hpp): the mean of the
// scene seen from above, one material of the .mat, or nothing.
enum class BackgroundChoice { Mean, Material, None };

// What --convergence's threshold bounds (trace(1) --convergence-error), with SE the
// largest over the bands of a pixel's standard error after n samples: SE / |mean|
// (relative), SE in W cm-2 sr-1 um-1 (absolute), or SE sqrt(MIN / n) (rms: a pixel stops
// when another sample would lower its variance by less than threshold^2 / MIN, which
// spends samples in proportion to the pixel's spread, the allocation that minimises the
// image's summed variance for a given number of samples), or max_b SE_b / L_grey,b x
// sqrt(MIN / n) (scene: rms in units of each band's radiance at the sensor of a 20 %
// grey Lambertian ground seen at nadir under the .rad's sun and sky,
// TraceContext::grey_radiance, so one threshold fits any scene's brightness; a band
// whose L_grey is not positive, a night's, is judged relative). Under scene, a pixel
// that stopped after n samples has SE_b < THRESHOLD L_grey,b sqrt(n / MIN).
enum class ConvergenceError { Relative, Absolute, Rms, Scene };

struct RenderOptions {
    Sampling sampling = Sampling::Golfball;
    long samples_per_pixel = 1;    // primary rays per pixel, stratified (White (1996), section 5.1.4 rec. 7)
    long hemisphere_samples = 64;  // montecarlo: rays per hit; dirsig: diffuse pattern size
    // golfball: draw each cell's ray at random inside its cell (cosine-weighted),
    // instead of at its centre: a stratified, unbiased estimator whose error falls
    // with samples_per_pixel; off = the fixed pattern of White (1996).
    bool golfball_jitter = false;
    int max_transmissions = 8;         // transmissive facets followed per ray
    // Secondary hits followed: at depth d < bounces a hit is shaded with its own
    // one-ray hemisphere estimate (a path), at depth = bounces it is closed with the
    // sun and an unobstructed sky (White (1996), section 5.2.3 step 4); 0: black;
    // kAutoBounces: as deep as the scene needs (bounce_estimate.hpp).
    int bounces = kAutoBounces;
    std::uint64_t seed = 1;            // results depend only on seed (not on threads)
    unsigned threads = 0;              // 0: all cores
    long row_begin = 0, row_end = -1;  // [begin, end); -1: to the last row
    bool truth = false;
    // With truth: the sampling layers after the others, "samples" (primary samples the
    // pixel took) and one "standard_error_BAND" per band: the standard error of the
    // pixel's mean radiance at the sensor, sqrt(s^2 / n) over its n primary samples at
    // the band-centre spectral sample (-1 below 2 samples; trace(1) --standard-error).
    bool sampling_layers = false;
    // --convergence MIN,MAX,THRESHOLD: primary samples in batches of convergence_min
    // at the points of the pixel's (0,2)-sequence until the error convergence_error
    // names is under convergence_threshold, or convergence_max samples are taken;
    // samples_per_pixel is then unused. 0: off.
    long convergence_min = 0, convergence_max = 0;
    double convergence_threshold = 0;
    ConvergenceError convergence_error = ConvergenceError::Relative;
    BackgroundChoice background = BackgroundChoice::Mean;
    long background_material = 0;  // MATERIAL_ID, with BackgroundChoice::Material
    // --sky-lookup table:N: rays that leave the scene upward read the sky from an N x N
    // table (radiometry/sky_table.hpp) instead of interpolating it; 0 (exact): they
    // interpolate (radiometry/sky_interpolation.hpp).
    int sky_table_side = 0;
    // --open-sky integrated (montecarlo): a primary hit's open-sky irradiance E(n) / pi
    // added whole from radiometry::SkyIrradiance, its hemisphere rays sampling only what
    // the scene changes (a control variate: rays that reach the sky carry no variance),
    // for materials whose hemisphere weight is (1 - s) cos / pi with a flat fall-off;
    // false (sampled): the rays sample the sky too.
    bool open_sky_integrated = false;
    double meters_per_unit = 1;  // scene units -> metres (transmission, range)
    // Ground-sky coupling and adjacency effect (adjacency.hpp; trace(1) RADIOMETRY):
    // on when the .rad has COUPLING terms; the environment's mean reflectance is taken
    // within this radius (metres) of the ground point the image centre sees.
    bool adjacency = true;
    double adjacency_radius_m = 1000;
    // With truth: one "uncertainty_BAND" layer per band after the others, the standard
    // uncertainty of the pixel radiance from RenderInputs::uncertainty (uncertainty.hpp;
    // trace(1) --uncertainty).
    bool uncertainty_layers = false;
    // golfball and montecarlo: the sun's image in each plane of the scene's mirror
    // (delta) facets lights every primary hit that sees it, when those facets lie in at
    // most this many planes (one ray toward each image and a shadow ray from the mirror;
    // tracer_sun_images.cpp); more planes, or 0: no image (said with --verbose).
    int sun_image_planes = 16;
};

// Facet temperatures (kelvin) by facet key ("1-1-1", "2.3/1-1-1"; tmp(5)).
using Temperatures = std::map<std::string, double>;

struct InputUncertainty;  // uncertainty.hpp

struct RenderInputs {
    const scene::Scene* scene = nullptr;
    const radiometry::Atmosphere* atmosphere = nullptr;
    const radiometry::MaterialLibrary* materials = nullptr;
    const Sensor* sensor = nullptr;
    const Temperatures* temperatures = nullptr;  // nullptr: no emission
    // The inputs' uncertainties; required with RenderOptions::uncertainty_layers.
    const InputUncertainty* uncertainty = nullptr;
};

struct RenderStats {
    std::uint64_t primary_rays = 0, secondary_rays = 0, shadow_rays = 0;
    std::uint64_t hits = 0;
    std::uint64_t sky_samples = 0, background_samples = 0;  // primary samples that left the scene
    std::uint64_t pixel_samples = 0;  // primary samples over all pixels (--convergence: varies)
    long max_pixel_samples = 0;       // the most one pixel took
    double seconds = 0;
    std::vector<std::string> skipped;  // what was not modelled, for --verbose
    std::string background;            // how the background world was made (world.hpp)
    std::string bounces;               // the bounce depth and its estimate, for --verbose
    std::string sky_lookup;            // how the sky is read (world.hpp), for --verbose
    std::string open_sky;              // --open-sky integrated's table, for --verbose
    std::string convergence_scale;     // --convergence-error scene's L_grey, for --verbose
};

}  // namespace sigchain::trace
