// Primary-ray generation: the Sensor interface the renderer draws its rays from, and
// the frame camera (camera_rays.cpp).
//
// This is where the line scanner and the pushbroom slot in beside the frame camera:
// each will implement Sensor, and its rays will then also carry the time at which
// they are taken and the platform pose (position and attitude) at that time; the
// renderer asks for nothing but a ray per image position and its view angle.
#pragma once

#include "geo/vec3.hpp"
#include "geom/camera.hpp"

namespace sigchain::trace {

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
    // Signed view angle (deg, the .rad's convention: find_min_max_view_angle(1)) of a
    // ray direction, for the path-term lookup.
    virtual double view_angle_deg(const geo::Vec3& direction) const = 0;
};

// The frame camera of a .adv (geom::FrameCamera): every ray from one position.
class FrameSensor final : public Sensor {
public:
    explicit FrameSensor(geom::FrameCamera camera);
    long rows() const override;
    long columns() const override;
    void ray(double row, double column, geo::Vec3& origin, geo::Vec3& direction) const override;
    double view_angle_deg(const geo::Vec3& direction) const override;

private:
    geom::FrameCamera m_camera;
    double m_reference_azimuth_deg = 0;
};

}  // namespace sigchain::trace
