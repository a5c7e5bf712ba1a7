// build_radiance's spectral samples solved in parallel (see solve_samples.hpp): the
// samples' results packed into the farm's messages and gathered on rank 0.
#include "atmos_table/solve_samples.hpp"

#include <cstdint>
#include <cstring>
#include <functional>
#include <type_traits>

#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/parallel.hpp"

namespace sigchain::atmos_table {
namespace {

// A part of the samples' results as bytes (the farm's message): per sample its fixed
// fields, then its series, each with its length.
void put_bytes(FarmBytes& out, const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    out.insert(out.end(), p, p + n);
}
template <class T>
void put_series(FarmBytes& out, const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = static_cast<std::uint64_t>(v.size());
    put_bytes(out, &n, sizeof n);
    put_bytes(out, v.data(), sizeof(T) * v.size());
}
struct Reader {
    const FarmBytes& bytes;
    std::size_t at = 0;
    void take(void* to, std::size_t n) {
        if (at + n > bytes.size()) throw IoError("MPI: a malformed part of spectral samples");
        std::memcpy(to, bytes.data() + at, n);
        at += n;
    }
    template <class T>
    std::vector<T> series() {
        std::uint64_t n = 0;
        take(&n, sizeof n);
        std::vector<T> v(static_cast<std::size_t>(n));
        take(v.data(), sizeof(T) * v.size());
        return v;
    }
};
struct SampleScalars {
    io::RadSample sample;
    double ground_irradiance, spherical_albedo, diffuse_down;
    std::int32_t terms;  // exponential-sum terms solved (the -v count)
    std::uint8_t thermal;
};

FarmBytes pack(const SampleResult* r, long count) {
    FarmBytes out;
    for (long i = 0; i < count; ++i, ++r) {
        const SampleScalars s{r->sample,
                              r->ground_irradiance,
                              r->spherical_albedo,
                              r->diffuse_down,
                              r->terms,
                              static_cast<std::uint8_t>(r->thermal)};
        put_bytes(out, &s, sizeof s);
        put_series(out, r->path);
        for (const auto* v : {&r->ls, &r->le, &r->us, &r->ue, &r->diffuse_up}) put_series(out, *v);
    }
    return out;
}

void unpack(const FarmBytes& bytes, SampleResult* r, long count) {
    Reader in{bytes};
    for (long i = 0; i < count; ++i, ++r) {
        SampleScalars s;
        in.take(&s, sizeof s);
        r->sample = s.sample;
        r->ground_irradiance = s.ground_irradiance;
        r->spherical_albedo = s.spherical_albedo;
        r->diffuse_down = s.diffuse_down;
        r->terms = s.terms;
        r->thermal = s.thermal != 0;
        r->path = in.series<io::RadPathSample>();
        for (auto* v : {&r->ls, &r->le, &r->us, &r->ue, &r->diffuse_up}) *v = in.series<double>();
    }
    if (in.at != bytes.size()) throw IoError("MPI: a malformed part of spectral samples");
}

}  // namespace

bool solve_samples(const std::vector<SampleSetup>& setups, const std::vector<std::size_t>& setup_of,
                   const std::vector<double>& nus, const Reporter& reporter,
                   std::vector<SampleResult>& results) {
    results.assign(nus.size(), {});
    const ProgressScope bar(reporter, "spectral samples");
    const auto solve = [&](long begin, long end, SampleResult* out,
                           const std::function<void(long, long)>& progress) {
        const unsigned threads = setups.front().options.threads;
        parallel_for(end - begin, {threads, progress}, [&](long i, unsigned) {
            const auto k = static_cast<std::size_t>(begin + i);
            out[i] = solve_sample(setups[setup_of[k]], nus[k]);
        });
    };
    const long n = static_cast<long>(nus.size());
    FarmJob job;
    job.items = n;
    job.parts = farm_parts(n, farm_workers(), 1e5);  // a sample's grids: kB, not GB
    job.compute = [&](long begin, long end) {
        std::vector<SampleResult> part(static_cast<std::size_t>(end - begin));
        solve(begin, end, part.data(), {});
        return pack(part.data(), end - begin);
    };
    const auto progress = bar.callback();
    long done = 0;
    job.gather = [&](long begin, long end, const FarmBytes& bytes) {
        unpack(bytes, results.data() + begin, end - begin);
        done += end - begin;
        if (progress) progress(done, n);
    };
    switch (n > 0 ? run_farm(job) : FarmRole::Alone) {
        case FarmRole::Alone:
            solve(0, n, results.data(), progress);
            return !farm_worker();
        case FarmRole::Lead:
            return true;
        case FarmRole::Worker:
            return false;
    }
    return true;
}

}  // namespace sigchain::atmos_table
