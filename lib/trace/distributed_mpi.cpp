// trace's tile farm over MPI (distributed.hpp; trace(1), MPI): rank 0 hands out row
// tiles one at a time and gathers them, the other ranks render them.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>

#include "core/error.hpp"
#include "core/mpi.hpp"
#include "trace/distributed.hpp"

namespace sigchain::trace {

namespace {

constexpr int kTagResult = 1;  // worker -> rank 0: a rendered tile (or, empty, a request)
constexpr int kTagWork = 2;    // rank 0 -> worker: the next tile's rows (empty: stop)
// One tile's floats stay well under MPI's 2^31 - 1 bytes per message.
constexpr double kMaxTileBytes = 1024.0 * 1024.0 * 1024.0;
// render()'s note when no primary sample left the scene (render.cpp): a farm knows it
// only from the sum over its tiles.
constexpr const char* kNoWorldNote = "the world beyond the scene for primary rays (none left it)";

// MPI for the whole farm. On the way out of an error MPI is not finalised (that would
// wait for the other ranks): the process exits with its error, and the launcher ends
// the job (Open MPI's mpirun aborts every rank when one exits without MPI_Finalize).
class Farm {
public:
    Farm() : m_session(std::make_unique<mpi::Session>()) {}
    ~Farm() {
        if (std::uncaught_exceptions() > 0) (void)m_session.release();
    }
    const mpi::Session& session() const { return *m_session; }

private:
    std::unique_ptr<mpi::Session> m_session;
};

struct TileHeader {
    std::int64_t begin = 0, end = 0;
    std::uint64_t primary = 0, secondary = 0, shadow = 0, hits = 0, sky = 0, background = 0;
};

void append(std::vector<unsigned char>& out, const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    out.insert(out.end(), p, p + bytes);
}

// A worker's message: the header, then the radiance floats and the truth floats.
std::vector<unsigned char> pack(long begin, long end, const RenderResult& r) {
    TileHeader h;
    h.begin = begin;
    h.end = end;
    const RenderStats& s = r.stats;
    h.primary = s.primary_rays;
    h.secondary = s.secondary_rays;
    h.shadow = s.shadow_rays;
    h.hits = s.hits;
    h.sky = s.sky_samples;
    h.background = s.background_samples;
    std::vector<unsigned char> out;
    out.reserve(sizeof h + 4 * (r.radiance.data.size() + r.truth.data.size()));
    append(out, &h, sizeof h);
    append(out, r.radiance.data.data(), 4 * r.radiance.data.size());
    append(out, r.truth.data.data(), 4 * r.truth.data.size());
    return out;
}

// Test hook, not documented for users: SIGCHAIN_TEST_KILL_WORKER_AFTER_TILES=N makes a
// worker raise SIGKILL once it has sent N tiles (tests/cli/mpi.bats: a killed worker
// fails the run cleanly).
void kill_hook(long sent) {
    static const long after = [] {
        const char* v = std::getenv("SIGCHAIN_TEST_KILL_WORKER_AFTER_TILES");
        return v && *v ? std::atol(v) : -1L;
    }();
    if (after >= 0 && sent >= after) std::raise(SIGKILL);
}

void work(const RenderInputs& inputs, const RenderOptions& options) {
    const RenderResult none;
    std::vector<unsigned char> message = pack(0, 0, none);
    mpi::send(0, kTagResult, message.data(), message.size());
    for (long sent = 1;; ++sent) {
        const mpi::Message m = mpi::receive(0, kTagWork);
        std::int64_t rows[2] = {0, 0};
        if (m.bytes.size() != sizeof rows) throw IoError("MPI: a malformed tile assignment");
        std::memcpy(rows, m.bytes.data(), sizeof rows);
        if (rows[0] == rows[1]) return;
        RenderOptions o = options;
        o.row_begin = rows[0];
        o.row_end = rows[1];
        message = pack(rows[0], rows[1], render(inputs, o));
        mpi::send(0, kTagResult, message.data(), message.size());
        kill_hook(sent);
    }
}

// Rank 0's side: the tiles, their hand-out and their gathering into `whole`.
class Master {
public:
    Master(const RenderOptions& options, long rows, int workers, double bytes_per_row)
        : m_begin(options.row_begin),
          m_rows(rows),
          m_tiles(farm_tiles(rows, workers, bytes_per_row, kMaxTileBytes)) {}

    // Sends `worker` the next tile, or a stop when none is left.
    void assign(int worker) {
        std::int64_t rows[2] = {0, 0};
        if (m_next < m_tiles) {
            rows[0] = m_begin + static_cast<long>((__int128)m_next * m_rows / m_tiles);
            rows[1] = m_begin + static_cast<long>((__int128)(m_next + 1) * m_rows / m_tiles);
            ++m_next;
            ++m_outstanding;
        }
        mpi::send(worker, kTagWork, rows, sizeof rows);
    }
    bool outstanding() const { return m_outstanding > 0; }
    long tiles() const { return m_tiles; }

    // A tile's pixels into `whole` (rows [m_begin, m_begin + m_rows)); returns its rows.
    long gather(const mpi::Message& m, RenderResult& whole) {
        TileHeader h;
        if (m.bytes.size() < sizeof h) throw IoError("MPI: a malformed tile");
        std::memcpy(&h, m.bytes.data(), sizeof h);
        const long n = h.end - h.begin;
        const std::size_t rad = whole.radiance.channels * n * whole.radiance.columns;
        const std::size_t truth = whole.truth.channels * n * whole.truth.columns;
        if (m.bytes.size() != sizeof h + 4 * (rad + truth) || h.begin < m_begin ||
            h.end > m_begin + m_rows)
            throw IoError("MPI: a tile of rows " + std::to_string(h.begin) + ":" +
                          std::to_string(h.end) + " does not fit the image");
        const unsigned char* p = m.bytes.data() + sizeof h;
        for (image::Image* img : {&whole.radiance, &whole.truth}) {
            const std::size_t plane = static_cast<std::size_t>(n) * img->columns;
            for (int c = 0; c < img->channels; ++c, p += 4 * plane)
                std::memcpy(&img->at(c, h.begin - m_begin, 0), p, 4 * plane);
        }
        RenderStats& s = whole.stats;
        s.primary_rays += h.primary;
        s.secondary_rays += h.secondary;
        s.shadow_rays += h.shadow;
        s.hits += h.hits;
        s.sky_samples += h.sky;
        s.background_samples += h.background;
        --m_outstanding;
        return n;
    }

private:
    long m_begin, m_rows, m_tiles;
    long m_next = 0, m_outstanding = 0;
};

// An image of `rows` rows shaped like `empty` (of no rows), zero-filled.
void grow(image::Image& image, long rows) {
    image.rows = rows;
    image.data.assign(static_cast<std::size_t>(image.channels) * image.plane_size(), 0.0f);
}

void lead(const RenderInputs& inputs, const RenderOptions& options, int size,
          const Reporter& reporter, RenderResult& result) {
    const auto start = std::chrono::steady_clock::now();
    const long cam_rows = inputs.sensor->rows();
    const long end = options.row_end < 0 ? cam_rows : options.row_end;
    const long rows = end - options.row_begin;
    // The empty cubes and the render's notes (strategy, bounces, background) from a
    // render of no rows, made while the workers render their first tiles.
    RenderOptions none = options;
    none.row_end = none.row_begin;
    const double bytes_per_row =
        4.0 * static_cast<double>(inputs.sensor->columns()) *
        static_cast<double>(inputs.atmosphere->grid().size() +
                            (options.truth ? truth_layer_names(inputs.atmosphere->grid()).size()
                                           : 0));
    Master master(options, rows, size - 1, bytes_per_row);
    reporter.info("MPI: " + std::to_string(size - 1) + " worker(s), " +
                  std::to_string(master.tiles()) + " tiles of about " +
                  std::to_string(rows / master.tiles()) + " rows");
    for (int w = 1; w < size; ++w) master.assign(mpi::receive_any(kTagResult).source);
    result = render(inputs, none);
    grow(result.radiance, rows);
    if (options.truth) grow(result.truth, rows);
    ProgressScope bar(reporter, "rendering");
    const auto progress = bar.callback();
    long done = 0;
    while (master.outstanding()) {
        const mpi::Message m = mpi::receive_any(kTagResult);
        done += master.gather(m, result);
        if (progress) progress(done, rows);
        master.assign(m.source);
    }
    std::vector<std::string>& skipped = result.stats.skipped;
    skipped.erase(std::remove(skipped.begin(), skipped.end(), kNoWorldNote), skipped.end());
    if (result.stats.sky_samples + result.stats.background_samples == 0)
        skipped.emplace_back(kNoWorldNote);
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

bool distributed_worker() { return mpi::launched() && mpi::launched_rank() > 0; }

bool render_rows(const RenderInputs& inputs, const RenderOptions& options,
                 const Reporter& reporter, RenderResult& result) {
    if (!mpi::launched() || mpi::launched_size() < 2) {
        ProgressScope bar(reporter, "rendering");
        result = render(inputs, options, bar.callback());
        return true;
    }
    Farm farm;
    if (farm.session().rank() != 0) {
        work(inputs, options);
        return false;
    }
    lead(inputs, options, farm.session().size(), reporter, result);
    return true;
}

}  // namespace sigchain::trace
