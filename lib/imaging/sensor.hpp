// Primary-ray generation: the Sensor interface the renderer (lib/trace) draws its rays
// from, the frame camera (camera_rays.cpp), and the pushbroom and line scanners
// (scanners.cpp), whose rays leave the platform's pose at the time each pixel is taken
// (White (1996), sections 1.0 and 3.4: "frame cameras, line scanners, and pushbroom
// scanners"). The renderer asks for nothing but a ray per image position and its view
// angle; find_min_max_view_angle (view_angle.hpp) and the georeferencing (georef.hpp)
// ask the same.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "geo/vec3.hpp"
#include "imaging/camera.hpp"
#include "imaging/trajectory.hpp"
#include "io/adv.hpp"

namespace sigchain::imaging {

// A sensor's image geometry. Implementations are immutable after construction, so
// one sensor serves every render thread at once.
class Sensor {
public:
    virtual ~Sensor() = default;
    virtual long rows() const = 0;
    virtual long columns() const = 0;
    // Ray through image-plane position (row, column) in pixel units ((0, 0) = top-left
    // corner of the top-left pixel): origin (scene frame, scene units) and unit
    // direction (scene frame).
    virtual void ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const = 0;
    // The nominal line of sight of image position (row, column), for georeferencing
    // (georef.hpp fit_map_grid): ray() at pixel centres, continued between them without
    // the pixel's own footprint (a pushbroom's ray() within a pixel spans its
    // detector and its motion; this one moves on with the line time). Default: ray().
    virtual void nominal_ray(double row, double column, geo::Vec3& origin,
                             geo::Vec3& direction) const {
        ray(row, column, origin, direction);
    }
    // Signed view angle (deg, the .rad's convention: find_min_max_view_angle(1)) of a
    // ray direction, for the path-term lookup.
    virtual double view_angle_deg(const geo::Vec3& direction) const = 0;
    // The horizontal unit direction (z = 0) toward which view_angle_deg is positive, for
    // find_min_max_view_angle's report. Default (test sensors): north.
    virtual geo::Vec3 view_angle_reference() const { return {0, 1, 0}; }
    // The one point every ray leaves from, for a sensor that has one (a frame camera:
    // find_view_angles's bounding box is seen from it); none (the default) for a
    // sensor on a moving platform.
    virtual std::optional<geo::Vec3> viewpoint() const { return std::nullopt; }
    // The sensor model's name ("frame camera", "pushbroom scanner", "line scanner") and
    // a one-line description of its geometry for -v (defaults for test sensors).
    virtual std::string kind() const { return "sensor"; }
    virtual std::string summary() const { return kind(); }
};

// The frame camera of a .adv (FrameCamera): every ray from one position.
class FrameSensor final : public Sensor {
public:
    explicit FrameSensor(FrameCamera camera);
    long rows() const override;
    long columns() const override;
    void ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const override;
    double view_angle_deg(const geo::Vec3& direction) const override;
    geo::Vec3 view_angle_reference() const override;
    std::optional<geo::Vec3> viewpoint() const override { return m_camera.position; }
    std::string kind() const override { return "frame camera"; }
    std::string summary() const override;

private:
    FrameCamera m_camera;
    double m_reference_azimuth_deg = 0;
};

// A pushbroom scanner: a linear array of `detectors` across track (body y) at the focal
// plane; line k is exposed from t_k = start + k * line_period for the integration time.
// Image position (row, column) with row = k + u (0 <= u <= 1) takes the pose at
// t_k + u * integration and looks along body (x, y, f) with x = (u - 1/2) pitch
// (the detector's along-track extent) and y = (column - detectors/2) pitch, so a
// pixel's rays cover its detector's footprint smeared by the motion.
struct PushbroomGeometry {
    long lines = 0, detectors = 0;
    double focal_length_mm = 0, pitch_mm = 0;
    double line_period_s = 0, integration_time_s = 0, start_time_s = 0;
    double end_time_s() const {
        return start_time_s + static_cast<double>(lines - 1) * line_period_s + integration_time_s;
    }
};

// A whiskbroom line scanner: a mirror sweeps the scan angle theta from -half_angle to
// +half_angle across track (about body x) in each scan period; `detectors` side by side
// along track (ETM+: 16) each give one image line per scan, so scan s makes rows
// s * detectors ... (s + 1) * detectors - 1, the later rows further forward. Column c of
// `samples` looks at theta = half_angle (2 c / samples - 1), taken at the time
// start + (s + c / samples) scan_period (bidirectional: odd scans run backward in time,
// start + (s + 1 - c / samples) scan_period). Detector d, at along-track fraction u of
// its row, looks at alpha = (d + u - detectors/2) ifov ahead: body direction
// (sin alpha, cos alpha sin theta, cos alpha cos theta). With the scan-line corrector
// (ETM+'s SLC) alpha also turns back by (tf - 1/2) detectors ifov, tf the time fraction
// of the scan: the scan's footprint then advances with the platform instead of zigzagging
// when speed x scan_period = detectors x ifov x height.
struct LineScanGeometry {
    long scans = 0, samples = 0, detectors = 1;
    double half_angle_rad = 0, ifov_rad = 0;
    double scan_period_s = 0, start_time_s = 0;
    bool bidirectional = false;
    bool scan_line_corrector = false;
    double end_time_s() const { return start_time_s + static_cast<double>(scans) * scan_period_s; }
};

class PushbroomSensor final : public Sensor {
public:
    // Throws DataError (at the .trj's first or last record) when the trajectory does
    // not cover the image's time span.
    PushbroomSensor(Trajectory trajectory, PushbroomGeometry g);
    long rows() const override { return m_g.lines; }
    long columns() const override { return m_g.detectors; }
    void ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const override;
    // At t = start + (row - 1/2) line_period + integration/2, along body (0, y, f).
    void nominal_ray(double row, double column, geo::Vec3& origin,
                     geo::Vec3& direction) const override;
    double view_angle_deg(const geo::Vec3& direction) const override;
    geo::Vec3 view_angle_reference() const override { return m_reference; }
    std::string kind() const override { return "pushbroom scanner"; }
    std::string summary() const override;
    // The time (s) at which image position `row` is taken.
    double time_of(double row) const;

private:
    Trajectory m_trajectory;
    PushbroomGeometry m_g;
    geo::Vec3 m_reference{};  // horizontal across-track direction (view-angle sign)
};

class LineScannerSensor final : public Sensor {
public:
    LineScannerSensor(Trajectory trajectory, LineScanGeometry g);
    long rows() const override { return m_g.scans * m_g.detectors; }
    long columns() const override { return m_g.samples; }
    void ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const override;
    double view_angle_deg(const geo::Vec3& direction) const override;
    geo::Vec3 view_angle_reference() const override { return m_reference; }
    std::string kind() const override { return "line scanner"; }
    std::string summary() const override;
    double time_of(double row, double column) const;
    // The scan angle (rad) of image position `column`.
    double scan_angle_rad(double column) const;

private:
    Trajectory m_trajectory;
    LineScanGeometry m_g;
    geo::Vec3 m_reference{};
};

// The geodetic origin of the scene frame (the .snd's latitude and longitude, height 0 on
// WGS84), where a geodetic .trj (trj(5)) is placed.
struct SceneOrigin {
    double latitude_deg = 0, longitude_deg = 0;
};

// The sensor an .adv describes (adv(5)): its frame camera, or a pushbroom or line scanner
// on the platform of its `trajectory` (a .trj beside the .adv) or straight-flight keys.
// Throws DataError naming the .adv (or .trj) and line for missing, conflicting or
// inapplicable keys, a geodetic .trj without `origin`, and a trajectory that does not
// cover the image's time span.
std::unique_ptr<Sensor> make_sensor(const io::Adv& adv, const std::string& adv_path,
                                    std::optional<SceneOrigin> origin = std::nullopt);

}  // namespace sigchain::imaging
