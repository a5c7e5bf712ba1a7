// .gdb geometric database (man gdb(5)): the problem report (legal but degenerate
// geometry) and the polygon tests lib/scene shares.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "io/gdb.hpp"

namespace sigchain::io {

namespace {

// The largest distance between two vertices (0 when all coincide).
double facet_size(const std::vector<Vec3>& v) {
    double size = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j)
            size = std::max(size, geo::norm(geo::sub(v[i], v[j])));
    return size;
}

void facet_problems(const GdbFacet& f, std::vector<std::string>& out) {
    const auto& v = f.vertices;
    double size = facet_size(v);
    if (size == 0) {
        out.push_back("all vertices coincide");
        return;
    }
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j)
            if (geo::norm(geo::sub(v[i], v[j])) <= 1e-9 * size)
                out.push_back("vertices " + std::to_string(i + 1) + " and " +
                              std::to_string(j + 1) + " coincide");
    Vec3 n = newell_normal(v);
    double twice_area = geo::norm(n);
    if (twice_area <= 1e-9 * size * size) {
        out.push_back("zero area (collinear vertices)");
        return;
    }
    Vec3 unit{n[0] / twice_area, n[1] / twice_area, n[2] / twice_area};
    if (v.size() == 4) {
        Vec3 centre{};
        for (const auto& p : v)
            for (int k = 0; k < 3; ++k) centre[k] += p[k] / 4;
        double off = 0;
        for (const auto& p : v) off = std::max(off, std::abs(geo::dot(geo::sub(p, centre), unit)));
        if (off > kGdbPlanarTolerance * size)
            out.push_back("non-planar quad (a vertex is " + format_number(off) +
                          " from the plane, tolerance " +
                          format_number(kGdbPlanarTolerance * size) + ")");
    }
    double c = std::min(1.0, std::abs(geo::dot(unit, f.normal)) / geo::norm(f.normal));
    double off_deg = std::acos(c) * 180.0 / 3.14159265358979323846;
    if (off_deg > kGdbNormalToleranceDeg)
        out.push_back("normal is " + format_number(std::round(off_deg * 100) / 100) +
                      " deg off the plane of the vertices");
}

std::string label(const std::string& kind, const std::string& name, const std::string& id) {
    return kind + " " + sigchain::quoted(name) + " (" + id + ")";
}

}  // namespace

Vec3 newell_normal(const std::vector<Vec3>& v) {
    Vec3 n{};
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec3& a = v[i];
        const Vec3& b = v[(i + 1) % v.size()];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
    }
    return n;
}

std::string polygon_degeneracy(const std::vector<Vec3>& v) {
    double size = facet_size(v);
    if (size == 0) return "all vertices coincide";
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j)
            if (geo::norm(geo::sub(v[i], v[j])) <= 1e-9 * size)
                return "vertices " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                       " coincide";
    if (geo::norm(newell_normal(v)) <= 1e-9 * size * size) return "zero area (collinear vertices)";
    return "";
}

std::vector<std::string> gdb_problems(const Gdb& gdb) {
    std::vector<std::string> out;
    for (const auto& obj : gdb.objects) {
        std::string o = label("object", obj.name, obj.id);
        if (obj.parts.empty())
            out.push_back(SourceLocation{gdb.file, obj.line}.str() + ": " + o + ": no parts");
        for (const auto& part : obj.parts) {
            std::string p = o + ", " + label("part", part.name, part.id);
            if (part.facets.empty())
                out.push_back(SourceLocation{gdb.file, part.line}.str() + ": " + p + ": no facets");
            for (const auto& f : part.facets) {
                std::vector<std::string> found;
                facet_problems(f, found);
                for (const auto& what : found)
                    out.push_back(SourceLocation{gdb.file, f.line}.str() + ": " + p + ", " +
                                  label("facet", f.name, f.id) + ": " + what);
            }
        }
    }
    return out;
}

}  // namespace sigchain::io
