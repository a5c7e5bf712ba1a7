// Text and JSON reports of compare(1) (see report.hpp).
#include "compare/report.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>

#include "core/text.hpp"

namespace sigchain::compare {

namespace {

// 6 significant digits for reading by people; JSON uses format_number instead.
std::string short_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v == 0 ? 0.0 : v);  // no "-0"
    return buf;
}

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    return format_number(v == 0 ? 0.0 : v);
}

std::string band_title(const BandComparison& b, std::size_t band_count) {
    if (b.name == "combined")
        return "combined: per-pixel mean of the " + std::to_string(band_count - 1) + " bands";
    return "band " + b.name + ": synthetic band " + std::to_string(b.synthetic_band) +
           ", reference band " + std::to_string(b.reference_band);
}

void write_point_table(std::ostream& out, const PointComparison& cmp, const BandComparison& b) {
    std::size_t w = 5;
    for (const auto& n : cmp.point_names) w = std::max(w, n.size());
    out << std::left << std::setw(static_cast<int>(w)) << "point" << std::right << std::setw(12)
        << "synthetic" << std::setw(7) << "rank" << std::setw(12) << "reference" << std::setw(7)
        << "rank" << '\n';
    for (std::size_t i = 0; i < cmp.point_names.size(); ++i)
        out << std::left << std::setw(static_cast<int>(w)) << cmp.point_names[i] << std::right
            << std::setw(12) << short_number(b.synthetic.values[i]) << std::setw(7)
            << short_number(b.synthetic.ranks[i]) << std::setw(12)
            << short_number(b.reference.values[i]) << std::setw(7)
            << short_number(b.reference.ranks[i]) << '\n';
    out << "ROC   " << short_number(b.roc.rho) << " (" << stats::rank_method_name(b.roc.method)
        << ")\n";
    out << "RMS   " << short_number(b.rms) << '\n';
    out << "bias  " << short_number(b.bias) << " (synthetic - reference)\n";
}

void write_statistics(std::ostream& out, const PointComparison& cmp) {
    out << "image statistics (whole images; population standard deviation)\n";
    out << std::left << std::setw(8) << "band" << std::right;
    for (const char* h : {"syn_mean", "ref_mean", "syn_std", "ref_std", "syn_median", "ref_median"})
        out << std::setw(12) << h;
    out << '\n';
    for (const auto& b : cmp.bands) {
        out << std::left << std::setw(8) << b.name << std::right;
        for (double v : {b.synthetic.mean, b.reference.mean, b.synthetic.std, b.reference.std,
                         b.synthetic.median, b.reference.median})
            out << std::setw(12) << short_number(v);
        out << '\n';
    }
}

void write_histogram(std::ostream& out, const BandComparison& b) {
    const auto& hs = b.synthetic.histogram;
    const auto& hr = b.reference.histogram;
    out << "histogram " << (b.name == "combined" ? b.name : "band " + b.name) << ": "
        << hs.counts.size() << " bins over [" << short_number(hs.lo) << ", " << short_number(hs.hi)
        << "], pixel counts\n";
    out << std::setw(12) << "from" << std::setw(12) << "to" << std::setw(12) << "synthetic"
        << std::setw(12) << "reference" << '\n';
    for (std::size_t i = 0; i < hs.counts.size(); ++i)
        out << std::setw(12) << short_number(hs.edge(i)) << std::setw(12)
            << short_number(hs.edge(i + 1)) << std::setw(12) << hs.counts[i] << std::setw(12)
            << hr.counts[i] << '\n';
}

void json_array(std::ostream& out, const std::vector<double>& values) {
    out << '[';
    for (std::size_t i = 0; i < values.size(); ++i)
        out << (i ? ", " : "") << json_number(values[i]);
    out << ']';
}

void json_side(std::ostream& out, const Side& s, const char* indent) {
    out << "{\n" << indent << "  \"values\": ";
    json_array(out, s.values);
    out << ",\n" << indent << "  \"ranks\": ";
    json_array(out, s.ranks);
    out << ",\n"
        << indent << "  \"mean\": " << json_number(s.mean) << ",\n"
        << indent << "  \"std\": " << json_number(s.std) << ",\n"
        << indent << "  \"median\": " << json_number(s.median) << ",\n"
        << indent << "  \"histogram\": [";
    for (std::size_t i = 0; i < s.histogram.counts.size(); ++i)
        out << (i ? ", " : "") << s.histogram.counts[i];
    out << "]\n" << indent << '}';
}

void json_band(std::ostream& out, const BandComparison& b) {
    const char* in = "      ";
    out << "    {\n"
        << in << "\"name\": " << json_string(b.name) << ",\n"
        << in << "\"synthetic_band\": " << b.synthetic_band << ",\n"
        << in << "\"reference_band\": " << b.reference_band << ",\n"
        << in << "\"roc\": " << json_number(b.roc.rho) << ",\n"
        << in << "\"roc_method\": " << json_string(stats::rank_method_name(b.roc.method)) << ",\n"
        << in << "\"rms\": " << json_number(b.rms) << ",\n"
        << in << "\"bias\": " << json_number(b.bias) << ",\n";
    std::vector<double> edges;
    for (std::size_t i = 0; i <= b.synthetic.histogram.counts.size(); ++i)
        edges.push_back(b.synthetic.histogram.edge(i));
    out << in << "\"histogram_edges\": ";
    json_array(out, edges);
    out << ",\n" << in << "\"synthetic\": ";
    json_side(out, b.synthetic, in);
    out << ",\n" << in << "\"reference\": ";
    json_side(out, b.reference, in);
    out << "\n    }";
}

}  // namespace

std::string json_string(const std::string& text) {
    std::string s = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') {
            s += '\\';
            s += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            s += buf;
        } else {
            s += c;
        }
    }
    return s + '"';
}

void write_text_report(std::ostream& out, const PointComparison& cmp) {
    out << "synthetic  " << cmp.synthetic_path << " (" << cmp.synthetic_rows << " rows, "
        << cmp.synthetic_columns << " columns)\n"
        << "reference  " << cmp.reference_path << " (" << cmp.reference_rows << " rows, "
        << cmp.reference_columns << " columns)\n"
        << "points     " << cmp.cpt_path << " (" << cmp.point_names.size()
        << " control points; rank 1 = lowest value)\n";
    for (const auto& b : cmp.bands) {
        out << '\n' << band_title(b, cmp.bands.size()) << '\n';
        write_point_table(out, cmp, b);
    }
    out << '\n';
    write_statistics(out, cmp);
    for (const auto& b : cmp.bands) {
        out << '\n';
        write_histogram(out, b);
    }
}

void write_json_report(std::ostream& out, const PointComparison& cmp) {
    out << "{\n  \"synthetic\": {\"path\": " << json_string(cmp.synthetic_path)
        << ", \"rows\": " << cmp.synthetic_rows << ", \"columns\": " << cmp.synthetic_columns
        << "},\n  \"reference\": {\"path\": " << json_string(cmp.reference_path)
        << ", \"rows\": " << cmp.reference_rows << ", \"columns\": " << cmp.reference_columns
        << "},\n  \"control_points\": " << json_string(cmp.cpt_path) << ",\n  \"points\": [";
    for (std::size_t i = 0; i < cmp.point_names.size(); ++i)
        out << (i ? ", " : "") << json_string(cmp.point_names[i]);
    out << "],\n  \"bands\": [\n";
    for (std::size_t i = 0; i < cmp.bands.size(); ++i) {
        json_band(out, cmp.bands[i]);
        out << (i + 1 < cmp.bands.size() ? ",\n" : "\n");
    }
    out << "  ]\n}\n";
}

void write_text_report(std::ostream& out, const PixelComparison& cmp) {
    out << "synthetic  " << cmp.synthetic_path << '\n'
        << "reference  " << cmp.reference_path << '\n'
        << "pixels     " << cmp.rows << " rows, " << cmp.columns
        << " columns; d = synthetic - reference\n"
        << "rms = sqrt(mean(d^2)), bias = mean(d), max_abs = max |d|,\n"
        << "mean_relative = mean |d|/|reference| over pixels where reference != 0\n\n";
    // Columns are separated by at least one space: "%.6g" of a negative number in
    // exponent form (-1.08729e-05) is 12 characters wide.
    out << std::left << std::setw(6) << "band" << std::right << std::setw(10) << "syn_band"
        << std::setw(10) << "ref_band" << std::setw(14) << "rms" << std::setw(14) << "bias"
        << std::setw(14) << "max_abs" << std::setw(14) << "mean_relative" << '\n';
    for (const auto& b : cmp.bands) {
        out << std::left << std::setw(6) << b.name << std::right << std::setw(10)
            << (b.synthetic_band ? std::to_string(b.synthetic_band) : "-") << std::setw(10)
            << (b.reference_band ? std::to_string(b.reference_band) : "-");
        for (double v : {b.rms, b.bias, b.max_abs, b.mean_relative})
            out << ' ' << std::setw(13) << short_number(v);
        out << '\n';
    }
}

void write_json_report(std::ostream& out, const PixelComparison& cmp) {
    out << "{\n  \"synthetic\": " << json_string(cmp.synthetic_path)
        << ",\n  \"reference\": " << json_string(cmp.reference_path)
        << ",\n  \"rows\": " << cmp.rows << ",\n  \"columns\": " << cmp.columns
        << ",\n  \"bands\": [\n";
    for (std::size_t i = 0; i < cmp.bands.size(); ++i) {
        const auto& b = cmp.bands[i];
        out << "    {\"name\": " << json_string(b.name)
            << ", \"synthetic_band\": " << b.synthetic_band
            << ", \"reference_band\": " << b.reference_band << ", \"rms\": " << json_number(b.rms)
            << ", \"bias\": " << json_number(b.bias) << ", \"max_abs\": " << json_number(b.max_abs)
            << ", \"mean_relative\": " << json_number(b.mean_relative)
            << ", \"relative_pixels\": " << b.relative_pixels << '}'
            << (i + 1 < cmp.bands.size() ? ",\n" : "\n");
    }
    out << "  ]\n}\n";
}

}  // namespace sigchain::compare
