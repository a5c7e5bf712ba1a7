// PNG histograms drawn with OpenImageIO (see plot.hpp).
#include "compare/plot.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "core/error.hpp"
#include "core/output.hpp"

namespace sigchain::compare {

namespace {

constexpr int kMargin = 8;        // pixels around the plot area
constexpr int kPlotWidth = 256;   // pixels, before rounding to whole bars
constexpr int kPlotHeight = 160;  // pixels

// Top row of a bar of `count` out of `max_count` over the base row.
int bar_top(long count, long max_count, int base) {
    if (count == 0 || max_count == 0) return base;
    int height = static_cast<int>(static_cast<double>(count) * (kPlotHeight - 1) /
                                  static_cast<double>(max_count));
    return base - std::max(height, 1);
}

}  // namespace

void write_histogram_plot(const std::string& path, const BandComparison& band) {
    const auto& syn = band.synthetic.histogram.counts;
    const auto& ref = band.reference.histogram.counts;
    int bins = static_cast<int>(syn.size());
    int bar = std::max(2, kPlotWidth / std::max(bins, 1));
    int width = bins * bar + 2 * kMargin, height = kPlotHeight + 2 * kMargin;
    OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8));
    const float white[] = {1, 1, 1}, blue[] = {0.3f, 0.5f, 0.9f}, red[] = {0.85f, 0.1f, 0.1f},
                black[] = {0, 0, 0};
    OIIO::ImageBufAlgo::fill(buf, white);
    long max_count = 0;
    for (int i = 0; i < bins; ++i) max_count = std::max({max_count, syn[i], ref[i]});
    int base = kMargin + kPlotHeight - 1;
    for (int i = 0; i < bins; ++i) {
        int x1 = kMargin + i * bar, x2 = x1 + bar - 1;
        if (ref[i] > 0)
            OIIO::ImageBufAlgo::render_box(buf, x1, bar_top(ref[i], max_count, base), x2, base,
                                           blue, true);
        if (syn[i] > 0)
            OIIO::ImageBufAlgo::render_box(buf, x1, bar_top(syn[i], max_count, base), x2, base, red,
                                           false);
    }
    OIIO::ImageBufAlgo::render_box(buf, kMargin, base + 1, width - kMargin - 1, base + 1, black,
                                   true);
    // OpenImageIO opens its file itself: it goes into a private folder beside the target.
    const TempDir folder(path);
    const std::string temp = folder.file(std::filesystem::path(path).filename().string());
    if (!buf.write(temp, OIIO::TypeDesc::UINT8, "png"))
        throw IoError(path + ": cannot write: " + buf.geterror());
    commit_moves({{temp, path}});
}

void write_histogram_plots(const std::string& dir, const PointComparison& cmp) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw IoError(dir + ": cannot create the directory: " + ec.message());
    for (const auto& band : cmp.bands) {
        std::string name = band.name == "combined" ? "combined" : "band" + band.name;
        write_histogram_plot((std::filesystem::path(dir) / ("histogram_" + name + ".png")).string(),
                             band);
    }
}

}  // namespace sigchain::compare
