// What a ray sees when it leaves the scene (trace(1), THE WORLD BEYOND THE SCENE).
//
// - Above the horizon: the downwelled sky of the .rad, interpolated between its cells
//   (radiometry/sky_interpolation.hpp). A secondary ray takes it as it arrives at the
//   ground, with --sky-lookup table:N from that interpolation tabulated on N x N cells
//   and read by nearest cell (radiometry/sky_table.hpp). A primary ray (always
//   interpolated: the table's cells would show as steps in the image) takes the sky as
//   seen at the sensor's altitude (the "effective sky radiance" of White (1996),
//   section 3.4): the ground's sky less the path radiance of the air between ground
//   and sensor, over that air's transmittance,
//   L_eff = min(L_0, max(0, L_0 - L_p) / tau2), with tau2 and L_p the .rad's path terms
//   of the mirrored (downward) line of sight, which crosses the same air at the same
//   slant; exact for a sensor at the ground (tau2 = 1, L_p = 0).
// - Below the horizon: the background world, a horizontal Lambertian plane at the
//   height of the scene's lowest point, lit by the same sun and sky without shadows,
//   with the spectral reflectance (and, with emission, the temperature) of the
//   background: by default the mean of what the scene shows from above (64 x 64
//   vertical rays over its bounding box, each first hit's material at nadir), or one
//   material of the .mat (--background ID), or nothing (--background none: such rays
//   see 0, as before the background existed). A primary ray that meets the plane sees
//   it through the path terms of its view angle, like any ground point.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "geo/vec3.hpp"
#include "scene/scene.hpp"

namespace sigchain::imaging {
class Sensor;
}  // namespace sigchain::imaging

namespace sigchain::trace {

struct TraceContext;
using imaging::Sensor;

// The background plane, made once per render (make_background).
struct Background {
    bool enabled = false;
    double height = 0;              // scene z of the plane, scene units
    std::vector<double> radiance;   // leaving the plane, W cm-2 sr-1 um-1 per sample
    std::vector<double> reflectance;  // per sample
    double temperature_k = -1;      // with emission; -1 none
    std::string description;        // for --verbose
};

// The background of the render's options (BackgroundChoice), from the context's
// scene, materials, sun and sky. Throws DataError for --background ID naming a
// material the .mat does not have.
Background make_background(const TraceContext& c);

// What the scene shows from above: the first hit of side x side vertical rays cast
// down from above the scene at the centres of a regular grid over [x0, x1] x [y0, y1]
// (scene units), x outer, y inner; `keep(x, y)` false skips a grid point. `visit(hit,
// x, y)` is called for each hit. The background's and the adjacency environment's
// mean reflectance are both taken this way (each facet counts by its area seen from
// above).
void for_each_seen_from_above(const scene::Scene& scene, double x0, double x1, double y0,
                              double y1, int side, const std::function<bool(double, double)>& keep,
                              const std::function<void(const scene::Hit&, double, double)>& visit);

// The distance along `dir` from `origin` to the background plane, or a negative
// value when the ray does not meet it.
double background_distance(const Background& b, const geo::Vec3& origin, const geo::Vec3& dir);

// The sky at the ground along a secondary ray's `dir` (L_ds, plus L_de with emission;
// header) added to `out` (the context's n samples): the table when the context has
// one, else the interpolation. Nothing at or below the horizon.
void add_sky(const TraceContext& c, const geo::Vec3& dir, double* out);
// How add_sky reads the sky, for --verbose: "sky lookup: exact (...)" or
// "sky lookup: table N x N (...)".
std::string sky_lookup_description(const TraceContext& c);
// With --open-sky integrated, for --verbose: the table, how many of its nodes the render
// computed, and the materials it serves; "" otherwise.
std::string open_sky_description(const TraceContext& c);

// The effective sky radiance (header) of a primary ray `dir` (dir[2] > 0) into `out`;
// tau2, lus and lue are scratch; every buffer holds the context's n samples.
void effective_sky(const TraceContext& c, const Sensor& sensor, const geo::Vec3& dir, double* out,
                   double* tau2, double* lus, double* lue);

}  // namespace sigchain::trace
