// View-angle range of a sensor over a scene (White (1996), section 4.2.3.3, DIRSIG's
// find_min_max_view_angle): the range of angles the .snd and .rad tables must cover.
//
// A view angle is the angle between a ray from the sensor and nadir (-z), in
// degrees, signed: positive when the ray's horizontal part points along the
// reference azimuth, negative when it points against it. The reference azimuth is the
// sensor's (Sensor::view_angle_reference): for a frame camera, the horizontal
// direction of its line of sight or, for a line of sight within 0.01 deg of nadir (or
// zenith), the image's up direction made horizontal; for a scanner, its across-track
// direction.
#pragma once

#include <optional>
#include <string>

#include "imaging/camera.hpp"
#include "scene/scene.hpp"

namespace sigchain::imaging {

struct AngleRange {
    double min_deg = 0;
    double max_deg = 0;
    double increment_deg = 0;  // suggested
    std::size_t samples = 0;   // rays or corners that contributed
};

// The running minimum and maximum of the angles added.
struct AngleAccumulator {
    double lo = 1e300, hi = -1e300;
    std::size_t n = 0;
    void add(double v);
    AngleRange range() const;  // with suggested_increment_deg's increment
};

struct ViewAngleReport {
    AngleRange bounding_box;                  // "scene-bounding-box"
    std::optional<AngleRange> field_of_view;  // "field-of-view"; none if no ray hits
    AngleRange unclipped_field_of_view;       // image border rays, hit or not
    double reference_azimuth_deg = 0;         // clockwise from north (+y)
    std::size_t rays_cast = 0;
};

// Rays that leave the scene see the world beyond it (trace(1)): below the horizon the
// background plane through the path terms of their own view angle, above it the sky
// through those of the mirrored, downward line of sight. The view angle whose path
// terms such a ray needs: |angle| folded at the horizon (180 - |angle| above it),
// at most kWorldMaxViewAngleDeg, sign kept.
inline constexpr double kWorldMaxViewAngleDeg = 89;
double world_view_angle_deg(double view_angle_deg);

// A frame camera's reference direction (unit, z = 0) for the sign of its view angles.
Vec3 reference_direction(const FrameCamera& cam);
// Signed view angle (deg) of a ray direction from the sensor.
double signed_view_angle_deg(const Vec3& direction, const Vec3& reference);
// A round increment (1, 2 or 5 x 10^k deg) giving at least `min_steps` steps over
// the range, at most 1 deg and at least 0.01 deg.
double suggested_increment_deg(double min_deg, double max_deg, int min_steps = 10);

class Sensor;  // sensor.hpp

// Both methods for any sensor (White (1996), section 4.2.3.3). The field-of-view method
// casts sensor.ray() through every border pixel centre, the four image corners and an
// interior grid of at most `grid` x `grid` positions, each ray's angle by
// sensor.view_angle_deg (world_view_angle_deg's for a ray that misses; no field of view
// if no ray hits). The bounding-box method takes the scene box's corners from the
// sensor's one viewpoint (a frame camera), else from the origin of every border ray
// (a moving platform's positions over the image). Throws DataError if the scene is
// empty.
ViewAngleReport find_view_angles(const Sensor& sensor, const scene::Scene& scene, int grid = 256);

}  // namespace sigchain::imaging
