// The find_min_max_view_angle job: the sensor of the .adv, the scene, both methods; the
// .snd line and the table of both methods.
#include "imaging/view_angle_job.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/error.hpp"
#include "core/text.hpp"
#include "imaging/sensor.hpp"
#include "imaging/view_angle.hpp"
#include "io/adv.hpp"

namespace sigchain::imaging {

namespace {

std::string fixed(double v, int decimals) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    std::string s = buf;
    // A value that rounds to zero prints as 0, never -0 (at any number of decimals).
    bool zero = s.find_first_not_of("-0.") == std::string::npos;
    return zero && s.front() == '-' ? s.substr(1) : s;
}

int decimals_of(double increment) {
    return increment >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(increment) - 1e-9));
}

void row(std::ostream& out, const char* name, const AngleRange& r) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%-20s %10s %10s %10s %8zu\n", name, fixed(r.min_deg, 4).c_str(),
                  fixed(r.max_deg, 4).c_str(), fixed(r.increment_deg, 2).c_str(), r.samples);
    out << buf;
}

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
    const ViewAngleReport rep = find_view_angles(*sensor, sc, job.grid);
    write_view_angle_report(rep, job.method, job.snd_line, job.adv_path, job.scene_path, out);
}

std::string snd_view_angle_line(double min_deg, double max_deg, double inc) {
    // Round outward to the increment so the .rad table covers the whole range.
    double lo = std::floor(min_deg / inc + 1e-9) * inc;
    double hi = std::ceil(max_deg / inc - 1e-9) * inc;
    int d = std::max(1, decimals_of(inc));
    return fixed(lo, d) + " " + fixed(hi, d) + " " + fixed(inc, d);
}

scene::GeoOrigin parse_geo_origin(const std::string& text, const std::string& option) {
    auto fields = split_fields(text, true);
    auto bad = [&](const std::string& why) {
        return UsageError(option + " expects LAT,LON or LAT,LON,HEIGHT (" + why + "), found '" +
                          text + "'");
    };
    if (fields.size() != 2 && fields.size() != 3) throw bad("two or three numbers");
    double v[3] = {0, 0, 0};
    for (std::size_t i = 0; i < fields.size(); ++i) {
        try {
            v[i] = parse_double(fields[i], {option, 0}, "a number");  // an option: no line
        } catch (const DataError&) {
            throw bad("numbers");
        }
    }
    if (std::abs(v[0]) > 90) throw bad("latitude within -90..90 deg");
    if (std::abs(v[1]) > 360) throw bad("longitude within -360..360 deg");
    return {v[0], v[1], v[2]};
}

void write_view_angle_report(const ViewAngleReport& rep, ViewAngleMethod method, bool snd_line,
                             const std::string& adv_path, const std::string& scene_path,
                             std::ostream& out) {
    if (method == ViewAngleMethod::FieldOfView && !rep.field_of_view)
        throw DataError({adv_path, 0}, "no ray of the field of view hits the scene in " +
                                           scene_path + "; check the look angles");
    if (snd_line) {
        const AngleRange& r =
            method == ViewAngleMethod::FieldOfView ? *rep.field_of_view : rep.bounding_box;
        out << snd_view_angle_line(r.min_deg, r.max_deg, r.increment_deg)
            << "\t# min, max and increment of the view angle (deg, "
            << (method == ViewAngleMethod::FieldOfView ? "field-of-view" : "scene-bounding-box")
            << ")\n";
        return;
    }
    out << "# view angles off nadir (deg), positive toward azimuth "
        << fixed(rep.reference_azimuth_deg, 3) << " deg (clockwise from north)\n"
        << "# method                min_deg    max_deg  increment  samples\n";
    row(out, "scene-bounding-box", rep.bounding_box);
    if (rep.field_of_view)
        row(out, "field-of-view", *rep.field_of_view);
    else
        out << "field-of-view        none (no ray of the image hits the scene)\n";
    row(out, "unclipped-image", rep.unclipped_field_of_view);
}

}  // namespace sigchain::imaging
