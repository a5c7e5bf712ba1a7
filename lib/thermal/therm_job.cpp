// therm: facet temperatures at the scene time (see therm_job.hpp).
#include "thermal/therm_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>

#include "core/error.hpp"
#include "core/farm.hpp"
#include "core/output.hpp"
#include "core/parallel.hpp"
#include "geo/scene_clock.hpp"

namespace sigchain::thermal {

namespace {

constexpr double kKelvinOffset = 273.15;
// mat(5) UNITS: cal -> J, g cm-3 -> kg m-3, cm -> m.
constexpr double kJoulesPerCalorie = 4.184;

std::string num(double v) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << v;
    return s.str();
}

void require_positive(double value, const char* tag, const io::Material& m, const io::Mat& mat) {
    if (!(value > 0) || !std::isfinite(value))
        throw DataError({mat.file, m.line}, "material '" + m.name + "' (id " +
                                                std::to_string(m.id) + "): " + tag + " " +
                                                num(value) + " must be above 0 for therm");
}

double value_at(const io::Shd& shd, const io::ShdFacet& f, double t_h) {
    double k = (t_h - shd.time_hours(0)) / shd.step_hours;
    long k0 = std::clamp(static_cast<long>(std::floor(k)), 0L, shd.steps - 1);
    long k1 = std::min(k0 + 1, shd.steps - 1);
    double w = std::clamp(k - static_cast<double>(k0), 0.0, 1.0);
    double sum = 0;
    for (long p = 0; p < f.points; ++p)
        sum += (1 - w) * f.sunlit(k0, p) * f.sun_transmittance(k0, p) +
               w * f.sunlit(k1, p) * f.sun_transmittance(k1, p);
    return sum / static_cast<double>(f.points);
}

}  // namespace

FacetThermal resolve_facet(const SceneFacet& facet, const io::Mat& mat) {
    const io::Material* m = mat.find(facet.material_id);
    if (!m)
        throw DataError(facet.where, "facet " + facet.key + ": material " +
                                         std::to_string(facet.material_id) + " is not in " +
                                         mat.file);
    double thickness_cm = facet.thickness_cm;
    if (thickness_cm == -1) {
        if (!m->thickness_cm)
            throw DataError(facet.where, "facet " + facet.key +
                                             ": no thickness (the facet gives -1 and material '" +
                                             m->name + "' has no THICKNESS)");
        thickness_cm = *m->thickness_cm;
    }
    if (!(thickness_cm > 0) || !std::isfinite(thickness_cm))
        throw DataError(facet.where, "facet " + facet.key + ": thickness " + num(thickness_cm) +
                                         " cm must be above 0");
    require_positive(m->mass_density_g_cm3, "MASS_DENSITY", *m, mat);
    require_positive(m->specific_heat_cal_g_c, "SPECIFIC_HEAT", *m, mat);
    require_positive(m->thermal_conductivity_dcs, "THERMAL_CONDUCTIVITY", *m, mat);
    double power = facet.power != -1 ? facet.power : m->self_generated_power.value_or(-1);
    if (power == -1) power = 0;  // -1: none (the default of White (1996))
    double exposed = facet.exposed_area != -1 ? facet.exposed_area : m->exposed_area;
    if (!std::isfinite(power) || !std::isfinite(exposed))
        throw DataError(facet.where,
                        "facet " + facet.key + ": power and exposed area must be finite");

    FacetThermal f;
    f.slab.thickness_m = thickness_cm / 100.0;
    f.slab.density_kg_m3 = m->mass_density_g_cm3 * 1000.0;
    f.slab.specific_heat_j_kg_k = m->specific_heat_cal_g_c * kJoulesPerCalorie * 1000.0;
    f.slab.conductivity_w_m_k =
        m->thermal_conductivity_dcs * io::kWattsPerMeterKelvinPerDcsConductivity;
    f.slab.volumetric_power_w_m3 = power / f.slab.thickness_m;  // power in W m-2 of facet
    f.solar_absorptivity = m->visible_emissivity;
    f.thermal_emissivity = m->thermal_emissivity;
    // EXPOSED_AREA: 1 (or less) one face to the air, 2 both; between, the back's share.
    f.back_exposure = std::clamp(exposed - 1.0, 0.0, 1.0);
    f.normal = facet.normal;
    return f;
}

std::vector<double> sun_factors(const io::Shd& shd, const io::ShdFacet& facet,
                                const std::vector<EnvironmentStep>& env) {
    const double first = shd.time_hours(0), last = shd.time_hours(shd.steps - 1);
    const double tol = 1e-6;
    const bool daily = last - first >= 24 - tol;
    std::vector<double> out;
    out.reserve(env.size());
    for (const auto& e : env) {
        double t = e.time_h;
        if (t < first - tol && daily) t += 24 * std::ceil((first - t) / 24 - tol);
        if (t < first - tol || t > last + tol)
            out.push_back(1.0);
        else
            out.push_back(value_at(shd, facet, t));
    }
    return out;
}

namespace {

struct Inputs {
    io::Shd shd;
    io::Wth wth;
    io::Mat mat;
    io::Snd snd;
    std::vector<SceneFacet> facets;
};

// The inputs; degenerate facets the scene keeps are told as info (trace
// --shadow-history has warned about them).
Inputs read_inputs(const ThermJob& job, const Reporter& reporter) {
    Inputs in;
    in.shd = io::read_shd_file(job.shd_path);
    in.wth = io::read_wth_file(job.wth_path);
    in.mat = io::read_mat_file(job.mat_path);
    in.snd = io::read_snd_file(job.snd_path);
    // DEM objects are placed about the .snd's point, as trace places them.
    const scene::GeoOrigin origin{in.snd.latitude_deg, in.snd.longitude_east_deg, 0.0};
    std::vector<std::string> degenerate;
    in.facets =
        read_scene_facets(job.scene_path, origin, &degenerate, job.scene_input, job.threads);
    for (const std::string& m : degenerate) reporter.info(m);
    return in;
}

// The run's start: the .wth's first row, at least 24 h before the scene time.
double check_times(const Inputs& in, const ThermJob& job) {
    const double scene = in.shd.scene_time_hours;
    const double snd_scene = geo::scene_wth_hours(io::scene_site(in.snd));
    // No line in these three: the .shd header's time against the .snd's date and
    // time, and the .wth's rows as a whole (its rows keep no line numbers).
    if (std::abs(scene - snd_scene) > 1e-3)
        throw DataError({job.shd_path, 0}, "scene time " + num(scene) + " h differs from " +
                                               job.snd_path + "'s " + num(snd_scene) +
                                               " h (its GMT time less the GMT offset, on the "
                                               "scene's day)");
    if (in.wth.rows.empty()) throw DataError({job.wth_path, 0}, "no weather rows");
    const double start = in.wth.rows.front().time_h;
    if (scene - start < 24 - 1e-6)
        throw DataError({job.wth_path, 0},
                        "the weather window starts at " + num(start) +
                            " h, less than 24 h "
                            "before the scene time " +
                            num(scene) +
                            " h (the .wth holds 48 h with the scene in the second day)");
    return start;
}

}  // namespace

namespace {

// One facet to solve: its description and its history.
struct FacetTask {
    std::size_t row = 0;  // in the .tmp
    FacetThermal facet;
    const io::ShdFacet* history = nullptr;
};

struct FacetAnswer {
    double temperature_k = 0;
    double spinup_residual_k = 0;  // change from the run before
    int runs = 0;
};

// Runs of one facet over the whole window, each starting from the previous run's
// profile 24 h after the start (the same time of day: the first day repeated), the
// first from the air temperature; until two answers at the scene time agree within
// kSpinUpToleranceK or kSpinUpMaxRuns runs. The answer is the last run's.
FacetAnswer solve_facet(const FacetTask& task, const io::Shd& shd,
                        const std::vector<EnvironmentStep>& env, std::size_t i24) {
    const FacetThermal& f = task.facet;
    const auto sun = sun_factors(shd, *task.history, env);
    Slab slab(f.slab, slab_nodes(f.slab.thickness_m, kSlabCells, kSlabGrowth), env.front().air_k);
    std::vector<double> start = slab.temperatures_k();
    FacetAnswer answer;
    double previous = 0;
    for (int run = 1; run <= kSpinUpMaxRuns; ++run) {
        slab.set_temperatures_k(start);
        run_facet(f, env, sun, 0, i24, slab, nullptr);
        start = slab.temperatures_k();
        run_facet(f, env, sun, i24, env.size() - 1, slab, nullptr);
        answer.temperature_k = slab.front_k();
        answer.runs = run;
        if (run > 1) {
            answer.spinup_residual_k = std::abs(answer.temperature_k - previous);
            if (answer.spinup_residual_k < kSpinUpToleranceK) break;
        }
        previous = answer.temperature_k;
    }
    return answer;
}

// Solves tasks [begin, end) on `threads` threads (0: all cores) into answers[begin, end).
void solve_range(const std::vector<FacetTask>& tasks, const io::Shd& shd,
                 const std::vector<EnvironmentStep>& env, std::size_t i24, unsigned threads,
                 long begin, long end, FacetAnswer* answers) {
    parallel_for(end - begin, ParallelOptions{threads, {}}, [&](long i, unsigned) {
        answers[i] = solve_facet(tasks[static_cast<std::size_t>(begin + i)], shd, env, i24);
    });
}

// Solves every task, in this process or farmed out to MPI ranks (core/farm.hpp; each
// facet's answer depends on the facet alone, so the .tmp is the same); answers in task
// order. Returns false on an MPI worker, which has no answers.
bool solve_all(const std::vector<FacetTask>& tasks, const io::Shd& shd,
               const std::vector<EnvironmentStep>& env, std::size_t i24, unsigned threads,
               std::vector<FacetAnswer>& answers) {
    static_assert(std::is_trivially_copyable_v<FacetAnswer>);
    const long n = static_cast<long>(tasks.size());
    answers.assign(tasks.size(), {});
    FarmJob job;
    job.items = n;
    job.parts = farm_parts(n, farm_workers(), sizeof(FacetAnswer));
    job.compute = [&](long begin, long end) {
        FarmBytes bytes(static_cast<std::size_t>(end - begin) * sizeof(FacetAnswer));
        std::vector<FacetAnswer> part(static_cast<std::size_t>(end - begin));
        solve_range(tasks, shd, env, i24, threads, begin, end, part.data());
        std::memcpy(bytes.data(), part.data(), bytes.size());
        return bytes;
    };
    job.gather = [&](long begin, long end, const FarmBytes& bytes) {
        if (bytes.size() != static_cast<std::size_t>(end - begin) * sizeof(FacetAnswer))
            throw IoError("MPI: facets " + std::to_string(begin) + ":" + std::to_string(end) +
                          " came back malformed");
        std::memcpy(answers.data() + begin, bytes.data(), bytes.size());
    };
    if (n == 0) return !farm_worker();
    switch (run_farm(job)) {
        case FarmRole::Alone:
            solve_range(tasks, shd, env, i24, threads, 0, n, answers.data());
            return true;
        case FarmRole::Lead:
            return true;
        case FarmRole::Worker:
            return false;
    }
    return true;
}

void describe_model(const Inputs& in, double start, std::size_t steps, const ThermJob& job,
                    const EnvironmentSummary& summary, const Reporter& reporter) {
    reporter.info("run from " + num(start) + " h to the scene time " +
                  num(in.shd.scene_time_hours) + " h, " + std::to_string(steps) +
                  " backward-Euler steps of " + num(job.time_step_s) + " s; " +
                  std::to_string(kSlabCells) + " cells through each facet");
    if (summary.computed_insolation_steps > 0)
        reporter.info(std::to_string(summary.computed_insolation_steps) +
                      " steps with insolation computed (the .wth gives 0): clear-sky Meinel & "
                      "Meinel x sky exposure");
    reporter.info(
        "model: sky emissivity Brutsaert (1975) with Crawford & Duchon (1999) clouds "
        "(cloud fraction = 1 - sky exposure); convection h = 5.7 + 3.8 v (McAdams); the "
        "part of the view that is not sky is black at the air temperature");
    reporter.info(
        "units: mat(5) UNITS (SPECIFIC_HEAT cal/g/C, MASS_DENSITY g/cm3, THICKNESS cm, "
        "THERMAL_CONDUCTIVITY 0.04184 W/m/K per unit); SELF_GENERATED_POWER W/m2 of "
        "facet");
    const double first = in.shd.time_hours(0);
    if (in.shd.time_hours(in.shd.steps - 1) - first < 24 - 1e-6 && first > start)
        reporter.info("before the .shd's first step (" + num(first) +
                      " h) facets are taken as unshadowed (the history spans less than 24 h)");
}

// Fills the rows of fixed facets and returns the tasks of the others (in scene order).
std::vector<FacetTask> plan_facets(const Inputs& in, const ThermJob& job, const Reporter& reporter,
                                   ThermResult& result) {
    std::unordered_map<std::string, const io::ShdFacet*> history;
    for (const auto& f : in.shd.facets) history.emplace(f.id, &f);
    std::vector<FacetTask> tasks;
    std::unordered_set<long> reported;  // materials whose back face was reported
    for (const SceneFacet& sf : in.facets) {
        const std::size_t row = result.tmp.facets.size();
        result.tmp.facets.push_back({sf.key, 0, 0});
        if (sf.temperature_c != -1) {
            if (!(sf.temperature_c > -kKelvinOffset))
                throw DataError(sf.where, "facet " + sf.key + ": temperature " +
                                              num(sf.temperature_c) + " C is below absolute zero");
            result.tmp.facets.back().temperature_k = sf.temperature_c + kKelvinOffset;
            ++result.facets_fixed;
            reporter.info("facet " + sf.key + ": temperature fixed by the .gdb");
            continue;
        }
        auto it = history.find(sf.key);
        if (it == history.end())  // no line: the .shd lacks the record
            throw DataError({job.shd_path, 0},
                            "no history for facet " + sf.key + " of " + job.scene_path);
        FacetTask task{row, resolve_facet(sf, in.mat), it->second};
        task.facet.sky_view_factor = it->second->sky_view_factor;
        if (reported.insert(sf.material_id).second)
            reporter.info("material " + std::to_string(sf.material_id) + ": " +
                          (task.facet.back_exposure > 0
                               ? "back face exposed to the air x " + num(task.facet.back_exposure)
                               : std::string("back face insulated")) +
                          " (EXPOSED_AREA: 1 or less one face, 2 both)");
        tasks.push_back(std::move(task));
    }
    std::unordered_set<std::string> keys;
    for (const SceneFacet& sf : in.facets) keys.insert(sf.key);
    const auto unused = std::count_if(in.shd.facets.begin(), in.shd.facets.end(),
                                      [&](const io::ShdFacet& f) { return !keys.count(f.id); });
    if (unused > 0)
        reporter.warn(job.shd_path + ": " + std::to_string(unused) +
                      " facets with a history are not in " + job.scene_path + " (ignored)");
    return tasks;
}

}  // namespace

ThermResult compute_temperatures(const ThermJob& job, const Reporter& reporter) {
    if (!(job.time_step_s > 0) || job.time_step_s > 3600)
        throw UsageError("--time-step must be above 0 and at most 3600 s");
    const std::string inputs[] = {job.shd_path, job.wth_path, job.mat_path, job.scene_path,
                                  job.snd_path};
    if (std::count(std::begin(inputs), std::end(inputs), "-") > 1)
        throw UsageError("only one input can be standard input ('-')");
    const Inputs in = read_inputs(job, reporter);
    const double start = check_times(in, job);
    EnvironmentSummary summary;
    const auto env = sample_environment(in.wth, job.wth_path, in.snd, start,
                                        in.shd.scene_time_hours, job.time_step_s, &summary);
    const std::size_t i24 =
        std::min(env.size() - 1, static_cast<std::size_t>(std::lround(86400 / job.time_step_s)));
    describe_model(in, start, env.size() - 1, job, summary, reporter);

    ThermResult result;
    result.tmp.time_hours = in.shd.scene_time_hours;
    const std::vector<FacetTask> tasks = plan_facets(in, job, reporter, result);
    std::vector<FacetAnswer> answers;
    if (!solve_all(tasks, in.shd, env, i24, job.threads, answers)) {
        result.worker = true;
        return result;
    }
    for (std::size_t i = 0; i < tasks.size(); ++i) {
        result.tmp.facets[tasks[i].row].temperature_k = answers[i].temperature_k;
        if (answers[i].spinup_residual_k > result.spinup_residual_k ||
            result.spinup_facet.empty()) {
            result.spinup_residual_k = answers[i].spinup_residual_k;
            result.spinup_facet = result.tmp.facets[tasks[i].row].facet_id;
        }
        result.spinup_runs_max = std::max(result.spinup_runs_max, answers[i].runs);
    }
    result.facets_solved = static_cast<long>(tasks.size());
    return result;
}

void run_therm(const ThermJob& job, const Reporter& job_reporter) {
    // MPI ranks other than 0 read the same inputs: only rank 0 reports and writes.
    const Reporter silent;
    const Reporter& reporter = farm_worker() ? silent : job_reporter;
    const std::string inputs[] = {job.shd_path, job.wth_path, job.mat_path, job.scene_path,
                                  job.snd_path};
    if (farm_available() && std::count(std::begin(inputs), std::end(inputs), "-") > 0)
        throw UsageError("standard input cannot be read under mpirun: every rank reads the inputs");
    ThermResult r = compute_temperatures(job, reporter);
    if (r.worker) return;
    reporter.info(std::to_string(r.facets_solved) + " facets solved, " +
                  std::to_string(r.facets_fixed) + " fixed by the .gdb");
    if (!r.spinup_facet.empty())
        reporter.info("spin-up: up to " + std::to_string(r.spinup_runs_max) +
                      " runs per facet; residual " + num(r.spinup_residual_k) + " K (facet " +
                      r.spinup_facet + "), the change at the scene time from the run before");
    if (r.spinup_residual_k > kSpinUpToleranceK)
        reporter.warn("spin-up residual " + num(r.spinup_residual_k) + " K at facet " +
                      r.spinup_facet + " after " + std::to_string(kSpinUpMaxRuns) +
                      " runs (a longer weather window would help)");
    write_atomically(job.output_path, [&](std::ostream& out) { io::write_tmp(out, r.tmp); });
}

}  // namespace sigchain::thermal
