// The find_min_max_view_angle job: the sensor of the .adv, the scene, both methods.
#include "trace/view_angle_job.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "geom/camera.hpp"
#include "io/adv.hpp"

namespace sigchain::trace {

geom::ViewAngleReport find_view_angles(const Sensor& sensor, const scene::Scene& scene, int grid) {
    const scene::Bounds b = scene.bounds();
    if (b.empty()) throw DataError({}, "the scene has no facets");
    geom::ViewAngleReport rep;
    const geo::Vec3 ref = sensor.view_angle_reference();
    rep.reference_azimuth_deg =
        std::fmod(std::atan2(ref[0], ref[1]) * 180.0 / std::numbers::pi + 360.0, 360.0);

    geom::AngleAccumulator fov, border;
    std::vector<geo::Vec3> origins;  // of the border rays, for the bounding box
    std::size_t hits = 0;
    auto cast = [&](double row, double col, bool on_border) {
        geo::Vec3 o{}, d{};
        sensor.ray(row, col, o, d);
        const double angle = sensor.view_angle_deg(d);
        if (on_border) {
            border.add(angle);
            origins.push_back(o);
        }
        ++rep.rays_cast;
        if (scene.intersect(o, d)) {
            fov.add(angle);
            ++hits;
        } else
            fov.add(geom::world_view_angle_deg(angle));
    };
    const long rows = sensor.rows(), columns = sensor.columns();
    const double R = static_cast<double>(rows), C = static_cast<double>(columns);
    for (double r : {0.0, R})
        for (double c : {0.0, C}) cast(r, c, true);  // the image's outer corners
    for (long c = 0; c < columns; ++c) {
        cast(0.5, c + 0.5, true);
        cast(R - 0.5, c + 0.5, true);
    }
    for (long r = 0; r < rows; ++r) {
        cast(r + 0.5, 0.5, true);
        cast(r + 0.5, C - 0.5, true);
    }
    const int gr = static_cast<int>(std::min<long>(grid, rows));
    const int gc = static_cast<int>(std::min<long>(grid, columns));
    for (int i = 0; i < gr; ++i)
        for (int j = 0; j < gc; ++j) cast((i + 0.5) * R / gr, (j + 0.5) * C / gc, false);
    rep.unclipped_field_of_view = border.range();
    if (hits > 0) rep.field_of_view = fov.range();

    geom::AngleAccumulator box;
    for (const geo::Vec3& o : origins)
        for (int i = 0; i < 8; ++i) {
            const geo::Vec3 corner{(i & 1) ? b.upper[0] : b.lower[0],
                                   (i & 2) ? b.upper[1] : b.lower[1],
                                   (i & 4) ? b.upper[2] : b.lower[2]};
            const geo::Vec3 d{corner[0] - o[0], corner[1] - o[1], corner[2] - o[2]};
            if (geo::dot(d, d) > 0) box.add(sensor.view_angle_deg(d));
        }
    rep.bounding_box = box.range();
    return rep;
}

namespace {

// The scene's geodetic origin: --origin, or where a DEM given as the scene places itself.
std::optional<scene::GeoOrigin> scene_origin(const ViewAngleJob& job, const Reporter& reporter) {
    if (job.origin) return job.origin;
    std::optional<scene::GeoOrigin> origin = scene::lone_dem_origin(job.scene_path);
    if (origin) {
        char where[96];
        std::snprintf(where, sizeof where, "latitude %.6f deg, longitude %.6f deg",
                      origin->latitude_deg, origin->longitude_east_deg);
        reporter.info(job.scene_path + ": placed about its centre, " + where + " (no --origin)");
    }
    return origin;
}

}  // namespace

void run_view_angle_job(const ViewAngleJob& job, std::ostream& out, const Reporter& reporter) {
    const io::Adv adv = io::read_adv_file(job.adv_path);
    const std::optional<scene::GeoOrigin> geo_origin = scene_origin(job, reporter);
    // The sensor as trace makes it: its keys checked, its .trj found beside the .adv.
    std::optional<SceneOrigin> origin;
    if (geo_origin) origin = SceneOrigin{geo_origin->latitude_deg, geo_origin->longitude_east_deg};
    const std::unique_ptr<Sensor> sensor = make_sensor(adv, job.adv_path, origin);
    scene::LoadOptions load;
    load.scene_meters_per_unit = io::meters_per_unit(adv.units);
    // Geometry only: a degenerate facet is never hit, so a .gdb's or DEM's are skipped
    // silently (trace names them), a mesh file's as trace skips them (or refuses them);
    // nothing is shaded, so a lone mesh or DEM needs no materials.
    load.allow_degenerate = true;
    load.quiet_degenerate = true;
    load.geometry_only = true;
    load.origin = geo_origin;
    load.input = job.scene_input;
    scene::LoadReport report;
    const scene::Scene sc = scene::load_scene(job.scene_path, load, &report);
    for (const std::string& w : report.warnings) reporter.warn(w);
    // The scene as a whole and the whole field of view: conditions of no single line.
    if (sc.triangle_count() == 0) throw DataError({job.scene_path, 0}, "the scene has no facets");
    // A frame camera keeps lib/geom's own computation (its reference from the camera).
    const geom::ViewAngleReport rep =
        adv.sensor == io::SensorKind::Frame
            ? geom::find_view_angles(geom::frame_camera(adv, job.adv_path), sc, job.grid)
            : find_view_angles(*sensor, sc, job.grid);
    geom::write_view_angle_report(rep, job.method, job.snd_line, job.adv_path, job.scene_path, out);
}

}  // namespace sigchain::trace
