// Histogram plots through gnuplot (see plot.hpp).
#include "compare/plot.hpp"

#include <cstdio>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "core/error.hpp"
#include "core/output.hpp"
#include "core/process.hpp"

namespace sigchain::compare {

namespace {

// A gnuplot single-quoted string: '' stands for one quote inside it.
std::string quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) {
        if (c == '\'') out += '\'';
        if (c != '\n') out += c;
    }
    return out + "'";
}

std::string number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

std::string band_title(const PointComparison& cmp, const BandComparison& band) {
    std::ostringstream t;
    std::string syn = std::filesystem::path(cmp.synthetic_path).filename().string();
    std::string ref = std::filesystem::path(cmp.reference_path).filename().string();
    if (band.name == "combined")
        t << "combined bands: " << syn << " against " << ref;
    else
        t << "band " << band.name << ": " << syn << " band " << band.synthetic_band << " against "
          << ref << " band " << band.reference_band;
    t << " (whole images)";
    return t.str();
}

}  // namespace

std::string histogram_script(const BandComparison& band, const std::string& title) {
    const auto& syn = band.synthetic.histogram;
    const auto& ref = band.reference.histogram;
    if (syn.counts.size() != ref.counts.size())
        throw IoError("histogram_script: the two histograms have different bins");
    std::ostringstream s;
    s << "# compare --plot: both whole images' histograms on shared bins; run as\n"
         "#   gnuplot THIS.gp > THIS.png\n"
         "set terminal pngcairo noenhanced size 640,400 font 'sans,10'\n"
      << "set title " << quoted(title) << "\n"
      << "set xlabel 'pixel value'\n"
         "set ylabel 'pixels per bin'\n"
         "set key top right box opaque\n"
         "set yrange [0:*]\n"
         "set grid ytics\n"
         "set style fill solid 0.6 border -1\n"
         "# lower edge, upper edge, reference count, synthetic count\n"
         "$bins << EOD\n";
    for (std::size_t i = 0; i < syn.counts.size(); ++i)
        s << number(syn.edge(i)) << ' ' << number(syn.edge(i + 1)) << ' ' << ref.counts[i] << ' '
          << syn.counts[i] << '\n';
    s << "EOD\n"
         "plot $bins using (($1 + $2) / 2):3:($2 - $1) with boxes lc rgb '#4d80e6' "
         "title 'reference', \\\n"
         "     $bins using (($1 + $2) / 2):4:($2 - $1) with boxes fs empty lw 2 "
         "lc rgb '#d91a1a' title 'synthetic'\n";
    return s.str();
}

void write_histogram_plot(const std::string& path, const BandComparison& band,
                          const std::string& title) {
    std::filesystem::path script = std::filesystem::path(path).replace_extension(".gp");
    std::string text = histogram_script(band, title);
    write_atomically(script.string(), [&](std::ostream& out) { out << text; });
    std::string png = run_and_capture({"gnuplot", script.string()},
                                      "compare --plot draws with gnuplot: install gnuplot-nox");
    write_atomically(path, [&](std::ostream& out) { out << png; });
}

void write_histogram_plots(const std::string& dir, const PointComparison& cmp) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw IoError(dir + ": cannot create the directory: " + ec.message());
    for (const auto& band : cmp.bands) {
        std::string name = band.name == "combined" ? "combined" : "band" + band.name;
        write_histogram_plot((std::filesystem::path(dir) / ("histogram_" + name + ".png")).string(),
                             band, band_title(cmp, band));
    }
}

}  // namespace sigchain::compare
