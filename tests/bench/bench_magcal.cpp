// bench_magcal: the magnetometer calibration and the gyro Z scale-factor run against
// synthetic data with known truth (issue 6 benchmark; generator and goals from
// calibration-notes.md §3 and §5).
//
// Truth: |B| = 50 uT, inclination 60 deg (ENU field (0, 25, -43.3) uT), hard iron
// (25, -18, 12) uT, symmetric soft iron diag (1.10, 0.92, 1.02) with off-diagonals
// 0.03..0.05, white noise 0.3 uT per axis. Each scenario runs --trials Monte Carlo trials
// (fixed seeds) and reports the 95th percentile:
//   hard-iron error |b^ - b|, soft-iron error ||M / cbrt(det M) - I||_F with M = S^ A,
//   heading error: max over a noise-free grid (yaw 0..355 step 5, roll and pitch in
//   {0, +-20} deg), tilt-compensated with the true attitude.
// Coverage sweep (the accuracy the data can give): full spheres of 50..1000 samples and
// 0.1..1 uT noise, caps of 75 % down to 25 % of the field directions, hemispheres, and
// bands (any yaw, roll and pitch within +-X). Per trial the fit's predicted heading error
// (level module) is set against the true one over the same level turn, with the linear
// covariance of the same fit as the baseline, and with an "oracle" that knows each case's
// true median error (but not the trial's own geometry or noise). Goals: at most two passes in
// a thousand have a true error above 1 deg (twice the pass limit; a pass needs the 68 % bound
// within 0.5 deg and the 95 % bound within 1 deg, so calibrated bounds let a few through in
// thousands of trials: none can be promised), printed beside what the baseline would pass; the predicted hard-iron sigma follows the true RMS within a
// factor of 2 wherever the fit does not run away; the predicted bounds are calibrated: in
// every case the true error is below the predicted 68 % bound in 60-76 % of the fits given to
// the user and below the predicted 95 % bound in >= 90 % (a refused fit comes with no bound to
// trust; cases where fewer than 20 % of the trials were given are printed, not judged). The
// sweep runs --sweep-trials trials per case (400): a share of a perfectly calibrated 68 %
// bound over n trials scatters by sqrt(0.68 * 0.32 / n), 4.7 points at 100 and 2.3 at 400, and
// with a dozen cases judged at 100 trials one of them would leave 60-76 % by chance alone
// two times in three; at 400 about once in seventy. (A "within a factor of 2 of the trial's own
// error" target is printed, x2, but not judged: one draw of noise gives one error, and on
// part of the sphere that error varies so much from draw to draw that even the oracle, which
// knows the case's true median, reaches only 54-65 % there.)
// The gyro scale run drives the simulated HiPNUC module (0.5 % gyro scale error, a
// turntable doing two turns clockwise and two counter-clockwise) and feeds its HI91
// frames, with the device's own timestamps, to calib::GyroScaleRun.
//
//   bench_magcal [--trials N] [--sweep-trials N] [--seed N]
//
// Prints every figure with its target and PASS/FAIL; exit status 1 when one misses, 2 on
// bad arguments.
#include "calib/ellipsoid_fit.h"
#include "calib/gyro_scale_run.h"
#include "calib/mag_calibrator.h"
#include "calib/mag_fit_uncertainty.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/stream/stream_demux.h"
#include "sim/hipnuc_simulator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace imudesk;
using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Runs fn(i) for i in [0, n) on every core; each index once, in no particular order. The trials
// are independent (each has its own seeded generator) and land in their own slot, and the
// figures are added up in index order afterwards, so the output does not depend on the number
// of cores: only the runtime does.
template <class Fn>
void parallelFor(int n, const Fn &fn)
{
    const int threads = std::clamp(int(std::thread::hardware_concurrency()), 1, 16);
    std::vector<std::thread> pool;
    for (int w = 0; w < threads; ++w)
        pool.emplace_back([&, w] {
            for (int i = w; i < n; i += threads)
                fn(i);
        });
    for (std::thread &t : pool)
        t.join();
}

// splitmix64 with Box-Muller: the same numbers on every platform.
class Rng {
public:
    explicit Rng(uint64_t seed) : m_s(seed) {}
    uint64_t next()
    {
        uint64_t z = (m_s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double unit() { return (double(next() >> 11) + 0.5) * 0x1.0p-53; } // (0, 1)
    double normal()
    {
        if (m_haveSpare) {
            m_haveSpare = false;
            return m_spare;
        }
        const double r = std::sqrt(-2.0 * std::log(unit()));
        const double a = 2.0 * kPi * unit();
        m_spare = r * std::sin(a);
        m_haveSpare = true;
        return r * std::cos(a);
    }
    Quaterniond rotation()
    {
        Eigen::Vector4d v(normal(), normal(), normal(), normal());
        v.normalize();
        return Quaterniond(v[0], v[1], v[2], v[3]);
    }
    Vector3d direction()
    {
        return Vector3d(normal(), normal(), normal()).normalized();
    }

private:
    uint64_t m_s;
    double m_spare = 0;
    bool m_haveSpare = false;
};

struct Truth {
    Vector3d field{0.0, 25.0, -25.0 * std::sqrt(3.0)}; // ENU, |B| = 50, inclination 60
    Vector3d hardIron{25.0, -18.0, 12.0};
    Matrix3d a;
    Truth()
    {
        a << 1.10, 0.04, 0.03, 0.04, 0.92, 0.05, 0.03, 0.05, 1.02;
    }
    Vector3d measure(const Quaterniond &q) const { return a * (q.toRotationMatrix().transpose() * field) + hardIron; }
};

enum class Coverage { Full, Hemisphere, Cap25, Planar };

std::vector<Vector3d> generate(const Truth &t, Rng &rng, int n, Coverage cov, double noise, double spikeFraction)
{
    std::vector<Vector3d> out;
    out.reserve(size_t(n));
    // The axis of the hemisphere / cap, in the sensor frame, changes per trial.
    const Vector3d axis = rng.direction();
    const Vector3d fieldDir = t.field.normalized();
    while (int(out.size()) < n) {
        Quaterniond q;
        if (cov == Coverage::Planar) {
            q = Quaterniond(Eigen::AngleAxisd(rng.unit() * 2 * kPi, Vector3d::UnitZ()));
        } else {
            q = rng.rotation();
            const Vector3d body = q.toRotationMatrix().transpose() * fieldDir;
            if (cov == Coverage::Hemisphere && body.dot(axis) < 0)
                continue;
            if (cov == Coverage::Cap25 && body.dot(axis) < 0.5) // cap area (1 - cos 60)/2 = 25 %
                continue;
        }
        Vector3d m = t.measure(q) + noise * Vector3d(rng.normal(), rng.normal(), rng.normal());
        if (spikeFraction > 0 && rng.unit() < spikeFraction)
            m += 20.0 * rng.direction();
        out.push_back(m);
    }
    return out;
}

double wrapDeg(double a)
{
    while (a > 180)
        a -= 360;
    while (a < -180)
        a += 360;
    return a;
}

double headingOf(const Vector3d &nav)
{
    return std::atan2(nav.x(), nav.y()) / kDeg; // from north towards east
}

// Max heading error over the noise-free grid, tilt-compensated with the true attitude.
double headingErrorMax(const Truth &t, const calib::MagCalResult &r, bool levelOnly)
{
    const double truth = headingOf(t.field);
    double worst = 0;
    const std::vector<double> tilts = levelOnly ? std::vector<double>{0.0} : std::vector<double>{-20.0, 0.0, 20.0};
    for (int yaw = 0; yaw < 360; yaw += 5)
        for (double roll : tilts)
            for (double pitch : tilts) {
                const Quaterniond q = Eigen::AngleAxisd(yaw * kDeg, Vector3d::UnitZ())
                    * Eigen::AngleAxisd(pitch * kDeg, Vector3d::UnitX()) * Eigen::AngleAxisd(roll * kDeg, Vector3d::UnitY());
                const Vector3d m = t.measure(q);
                Vector3d c = r.correct(m);
                if (levelOnly)
                    c.z() = 0; // the 2-D calibration: heading from the horizontal components only
                const Vector3d nav = q.toRotationMatrix() * c;
                worst = std::max(worst, std::fabs(wrapDeg(headingOf(nav) - truth)));
            }
    return worst;
}

double softIronErrorPct(const Truth &t, const calib::MagCalResult &r)
{
    const Matrix3d m = r.softIron * t.a;
    const Matrix3d n = m / std::cbrt(m.determinant());
    return 100.0 * (n - Matrix3d::Identity()).norm();
}

double p95(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const size_t k = size_t(std::ceil(0.95 * double(v.size()))) - 1;
    return v[std::min(k, v.size() - 1)];
}

int g_failures = 0;

void report(const char *name, double value, const char *unit, const char *op, double target)
{
    const bool ok = std::strcmp(op, "<=") == 0 ? value <= target : std::strcmp(op, "<") == 0 ? value < target : value >= target;
    if (!ok)
        ++g_failures;
    std::printf("%-52s %10.4f %-4s target %s %-8.4g %s\n", name, value, unit, op, target, ok ? "PASS" : "FAIL");
}

struct Figures {
    std::vector<double> hi, si, heading;
    int refused = 0, trials = 0;
};

Figures runScenario(const Truth &t, uint64_t seed, int trials, int n, Coverage cov, double spikes,
                    calib::MagCalMode mode = calib::MagCalMode::Full3D)
{
    Figures f;
    calib::MagCalibrator::Options o;
    o.levelVerticalUt = t.field.z(); // the world model's vertical component (2-D mode)
    const calib::MagCalibrator cal(o);
    std::vector<calib::MagCalResult> results(size_t(std::max(trials, 0)));
    parallelFor(trials, [&](int i) {
        Rng rng(seed * 1000003ull + uint64_t(i) * 7919ull + uint64_t(cov) * 31ull + uint64_t(spikes * 1000));
        const auto samples = generate(t, rng, n, cov, 0.3, spikes);
        results[size_t(i)] = cal.calibrate(samples, mode);
    });
    for (const calib::MagCalResult &r : results) {
        ++f.trials;
        if (r.verdict == calib::MagVerdict::Refused)
            ++f.refused;
        // The fit's errors whatever its verdict (a fit refused for its accuracy still ran);
        // only data refused before any fit has none.
        if (r.verdict == calib::MagVerdict::Refused && std::isnan(r.predictedHeadingErrorDeg))
            continue;
        const bool planar = mode == calib::MagCalMode::Planar2D;
        f.hi.push_back(planar ? (r.hardIron - t.hardIron).head<2>().norm() : (r.hardIron - t.hardIron).norm());
        if (!planar)
            f.si.push_back(softIronErrorPct(t, r));
        f.heading.push_back(headingErrorMax(t, r, planar));
    }
    return f;
}

void magnetometer(uint64_t seed, int trials)
{
    const Truth t;
    std::printf("Magnetometer fit, %d trials per scenario, noise 0.3 uT, p95:\n", trials);
    const Figures full = runScenario(t, seed, trials, 300, Coverage::Full, 0);
    const double hi = p95(full.hi), si = p95(full.si), hd = p95(full.heading);
    report("full sphere N=300: hard-iron error", hi, "uT", "<=", 0.10);
    report("full sphere N=300: soft-iron error", si, "%", "<=", 0.4);
    report("full sphere N=300: heading error (max)", hd, "deg", "<=", 0.4);
    report("full sphere N=300: refused trials", full.refused, "", "<=", 0);

    const Figures hemi = runScenario(t, seed, trials, 300, Coverage::Hemisphere, 0);
    report("hemisphere N=300: hard-iron error", p95(hemi.hi), "uT", "<=", 0.7);
    // No longer a coverage verdict: each hemisphere is judged by its predicted accuracy (the sweep).
    std::printf("hemisphere N=300: heading error (max) %.4f deg (notes' G4 goal 1.0, not a target here); %d of %d "
                "trials refused for their predicted accuracy\n",
                p95(hemi.heading), hemi.refused, hemi.trials);

    for (double spikes : {0.02, 0.05}) {
        const Figures sp = runScenario(t, seed, trials, 300, Coverage::Full, spikes);
        const std::string tag = "spikes " + std::to_string(int(spikes * 100)) + " % (+20 uT): ";
        report((tag + "hard-iron error").c_str(), p95(sp.hi), "uT", "<=", 0.10 * 1.15);
        report((tag + "soft-iron error").c_str(), p95(sp.si), "%", "<=", 0.4 * 1.15);
        report((tag + "heading error (max)").c_str(), p95(sp.heading), "deg", "<=", 0.4 * 1.15);
    }

    const Figures cap = runScenario(t, seed, trials, 300, Coverage::Cap25, 0);
    report("25 % cap: full fit refused (share of trials)", 100.0 * cap.refused / cap.trials, "%", ">=", 100);
    const Figures planar = runScenario(t, seed, trials, 300, Coverage::Planar, 0);
    report("planar: full fit refused (share of trials)", 100.0 * planar.refused / planar.trials, "%", ">=", 100);
    const Figures planar2d = runScenario(t, seed, trials, 300, Coverage::Planar, 0, calib::MagCalMode::Planar2D);
    report("planar N=300, 2-D fit: level heading error (max)", p95(planar2d.heading), "deg", "<=", 0.3);
    report("planar N=300, 2-D fit: refused trials", planar2d.refused, "", "<=", 0);

    // Speed and determinism: 1000 points, full sphere.
    Rng rng(seed ^ 0xABCDEFull);
    const auto samples = generate(t, rng, 1000, Coverage::Full, 0.3, 0);
    const calib::MagCalibrator cal;
    std::vector<double> ms;
    calib::MagCalResult first;
    bool identical = true;
    for (int i = 0; i < 21; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const calib::MagCalResult r = cal.calibrate(samples);
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        if (i == 0) {
            first = r;
        } else {
            identical = identical && std::memcmp(r.hardIron.data(), first.hardIron.data(), sizeof(double) * 3) == 0
                && std::memcmp(r.softIron.data(), first.softIron.data(), sizeof(double) * 9) == 0
                && std::memcmp(&r.fieldUt, &first.fieldUt, sizeof(double)) == 0
                && std::memcmp(&r.fitErrorPct, &first.fitErrorPct, sizeof(double)) == 0;
        }
    }
    std::sort(ms.begin(), ms.end());
    report("fit of 1000 points: time (max of 21 runs)", ms.back(), "ms", "<", 50);
    report("fit of 1000 points: bit-identical on 20 repeats", identical ? 1 : 0, "", ">=", 1);
}

// One coverage of the sweep: field directions within a cap of `capFraction` of the sphere
// around an axis that changes per trial (1 = the full sphere), or, with bandDeg > 0, any
// yaw with roll and pitch uniform within +-bandDeg.
struct SweepCase {
    const char *name;
    int n;
    double noise;
    double capFraction;
    double bandDeg;
};

std::vector<Vector3d> generateSweep(const Truth &t, Rng &rng, const SweepCase &c)
{
    std::vector<Vector3d> out;
    out.reserve(size_t(c.n));
    const Vector3d axis = rng.direction();
    const Vector3d fieldDir = t.field.normalized();
    const double minDot = 1.0 - 2.0 * c.capFraction; // cap area (1 - cos a) / 2
    while (int(out.size()) < c.n) {
        Quaterniond q;
        if (c.bandDeg > 0) {
            const double yaw = rng.unit() * 2 * kPi;
            const double roll = (2 * rng.unit() - 1) * c.bandDeg * kDeg, pitch = (2 * rng.unit() - 1) * c.bandDeg * kDeg;
            q = Eigen::AngleAxisd(yaw, Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Vector3d::UnitX())
                * Eigen::AngleAxisd(roll, Vector3d::UnitY());
        } else {
            q = rng.rotation();
            if (c.capFraction < 1 && (q.toRotationMatrix().transpose() * fieldDir).dot(axis) < minDot)
                continue;
        }
        out.push_back(t.measure(q) + c.noise * Vector3d(rng.normal(), rng.normal(), rng.normal()));
    }
    return out;
}

// Largest heading error of a level module turned once (yaw 0..355 step 5), tilt
// compensated with the true attitude: the quantity the fit's prediction stands for.
double levelHeadingErrorMax(const Truth &t, const calib::MagCalResult &r)
{
    const double truth = headingOf(t.field);
    double worst = 0;
    for (int yaw = 0; yaw < 360; yaw += 5) {
        const Quaterniond q(Eigen::AngleAxisd(yaw * kDeg, Vector3d::UnitZ()));
        const Vector3d nav = q.toRotationMatrix() * r.correct(t.measure(q));
        worst = std::max(worst, std::fabs(wrapDeg(headingOf(nav) - truth)));
    }
    return worst;
}

double median(std::vector<double> v)
{
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double rms(const std::vector<double> &v)
{
    double s = 0;
    for (double x : v)
        s += x * x;
    return v.empty() ? 0 : std::sqrt(s / double(v.size()));
}

void coverageSweep(uint64_t seed, int trials)
{
    const Truth t;
    const SweepCase cases[] = {
        {"full, N=1000", 1000, 0.3, 1.0, 0},      {"full, N=300, 0.1 uT", 300, 0.1, 1.0, 0},
        {"full, N=300", 300, 0.3, 1.0, 0},         {"full, N=100", 100, 0.3, 1.0, 0},
        {"full, N=50", 50, 0.3, 1.0, 0},           {"full, N=300, 1 uT", 300, 1.0, 1.0, 0},
        {"cap 75 %", 300, 0.3, 0.75, 0},           {"hemisphere", 300, 0.3, 0.5, 0},
        {"hemisphere, N=1000", 1000, 0.3, 0.5, 0}, {"cap 37 %", 300, 0.3, 0.37, 0},
        {"cap 25 %", 300, 0.3, 0.25, 0},           {"band +-60", 300, 0.3, 1.0, 60},
        {"band +-45", 300, 0.3, 1.0, 45},          {"band +-30", 300, 0.3, 1.0, 30},
        {"band +-20", 300, 0.3, 1.0, 20},
    };
    const calib::MagCalibrator cal;
    std::printf("Coverage sweep, %d trials per case, noise per axis as named (else 0.3 uT), N=300 unless named.\n"
                "Heading error = the largest over one level turn; pred = the fit's predicted heading error; x2 = share\n"
                "of trials whose prediction is within a factor of 2 of their true error; oracle = the same share for a\n"
                "prediction that knew only the case's true median; linear = the covariance-only prediction (baseline);\n"
                "HI/SI = RMS of the true hard-iron (uT) / soft-iron (%%) errors and of their predicted sigmas;\n"
                "<68/<95 = share of the fits given (pass or warn) whose true error is below the predicted 68 %% / 95 %%\n"
                "bound, judged in the cases where at least 20 %% of the trials were given;\n"
                ">1ok = trials with a true error > 1 deg given pass (lin>1ok: had the baseline decided).\n",
                trials);
    std::printf("%-19s %7s %7s %7s | %4s %4s | %4s %6s %6s | %7s %7s %7s | %6s %6s | %4s %4s %4s %4s %4s %6s\n", "case",
                "pred", "true", "trueP95", "<68", "<95", "x2", "oracle", "linear", "HI", "HIpred", "HIlin", "SI", "SIpred",
                "pass", "warn", "ref", "fail", ">1ok", "lin>1ok");
    int within = 0, withinLinear = 0, withinOracle = 0, counted = 0, badPass = 0, badPassLinear = 0, passes = 0;
    double worstLow = 1e9, worstHigh = 0;
    double below68Low = 100, below68High = 0, below95Low = 100;
    const int kMinOffered = std::max(10, trials / 5);
    double fullPred = 0;
    for (const SweepCase &c : cases) {
        std::vector<double> pred, pred95, truth, linear, hiErr, hiPred, hiLin, siErr, siPred;
        std::vector<bool> given; // the fit was given to the user (pass or warn), with its bounds
        int verdicts[4] = {0, 0, 0, 0}, bad = 0, badLinear = 0;
        // Each trial's fit and its baseline (the linear covariance of the same fit), in parallel.
        struct Trial {
            calib::MagCalResult r;
            calib::MagFitUncertainty::Figures lin;
        };
        std::vector<Trial> runs(size_t(std::max(trials, 0)));
        parallelFor(trials, [&](int i) {
            Rng rng(seed * 2654435761ull + uint64_t(i) * 104729ull + uint64_t(c.n) * 13ull
                    + uint64_t(c.capFraction * 1000) * 17ull + uint64_t(c.bandDeg) * 19ull + uint64_t(c.noise * 100) * 23ull);
            const auto samples = generateSweep(t, rng, c);
            Trial &run = runs[size_t(i)];
            run.r = cal.calibrate(samples);
            if (std::isnan(run.r.predictedHeadingErrorDeg))
                return; // refused before any fit
            calib::Ellipsoid e;
            e.center = run.r.hardIron;
            e.w = run.r.softIron / run.r.fieldUt;
            run.lin = calib::MagFitUncertainty::ofEllipsoid(samples, e);
        });
        for (const Trial &run : runs) {
            const calib::MagCalResult &r = run.r;
            ++verdicts[int(r.verdict)];
            if (std::isnan(r.predictedHeadingErrorDeg))
                continue; // refused before any fit
            const double tr = levelHeadingErrorMax(t, r);
            bad += r.verdict == calib::MagVerdict::Pass && tr > 1.0;
            const auto &lin = run.lin;
            // What the baseline would have passed on its own.
            badLinear += lin.headingErrorDeg < calib::MagCalibrator::kWarnHeadingErrorDeg && tr > 1.0;
            pred.push_back(r.predictedHeadingErrorDeg);
            pred95.push_back(r.predictedHeadingError95Deg);
            given.push_back(r.verdict != calib::MagVerdict::Refused);
            truth.push_back(tr);
            linear.push_back(lin.headingErrorDeg);
            hiErr.push_back((r.hardIron - t.hardIron).norm());
            hiPred.push_back(r.hardIronSigmaUt);
            hiLin.push_back(lin.hardIronSigmaUt);
            siErr.push_back(softIronErrorPct(t, r));
            siPred.push_back(r.softIronSigmaPct);
        }
        auto share = [&](const std::function<double(size_t)> &p) {
            int n = 0;
            for (size_t k = 0; k < truth.size(); ++k)
                n += truth[k] <= 2 * p(k) && p(k) <= 2 * truth[k];
            return n;
        };
        const double med = median(truth);
        const int w = share([&](size_t k) { return pred[k]; });
        const int wl = share([&](size_t k) { return linear[k]; });
        const int wo = share([&](size_t) { return med; });
        const double n = double(std::max<size_t>(truth.size(), 1));
        // The bounds of the fits given to the user: a refused fit (a cap of 25 %, a narrow band,
        // where it runs away) is not offered with a bound to trust.
        int below68 = 0, below95 = 0, offered = 0;
        for (size_t k = 0; k < truth.size(); ++k) {
            if (!given[k])
                continue;
            ++offered;
            below68 += truth[k] <= pred[k];
            below95 += truth[k] <= pred95[k];
        }
        const double no = double(std::max(offered, 1));
        if (offered >= kMinOffered) {
            below68Low = std::min(below68Low, 100 * below68 / no);
            below68High = std::max(below68High, 100 * below68 / no);
            below95Low = std::min(below95Low, 100 * below95 / no);
        }
        std::printf("%-19s %7.3f %7.3f %7.3f | %3.0f%% %3.0f%% | %3.0f%% %5.0f%% %5.0f%% | %7.3f %7.3f %7.3f | %6.3f %6.3f | "
                    "%4d %4d %4d %4d %4d %6d\n",
                    c.name, median(pred), med, p95(truth), 100 * below68 / no, 100 * below95 / no, 100 * w / n, 100 * wo / n,
                    100 * wl / n, rms(hiErr), rms(hiPred), rms(hiLin), rms(siErr), rms(siPred), verdicts[0], verdicts[1],
                    verdicts[3], verdicts[2], bad, badLinear);
        within += w;
        withinLinear += wl;
        withinOracle += wo;
        counted += int(truth.size());
        badPass += bad;
        badPassLinear += badLinear;
        passes += verdicts[int(calib::MagVerdict::Pass)];
        if (std::strcmp(c.name, "full, N=300") == 0)
            fullPred = median(pred);
        // Where the fit stays near the truth (not the runaway fits of a 25 % cap or a narrow
        // band, which are refused), the predicted sigma must follow the true error.
        if (rms(hiErr) < 5.0) {
            worstLow = std::min(worstLow, rms(hiPred) / rms(hiErr));
            worstHigh = std::max(worstHigh, rms(hiPred) / rms(hiErr));
        }
    }
    const double all = double(std::max(counted, 1));
    std::printf("all cases: prediction within x2 of the true error in %.1f %% of %d trials (oracle %.1f %%, linear %.1f %%)\n",
                100 * within / all, counted, 100 * withinOracle / all, 100 * withinLinear / all);
    report("coverage sweep: full sphere N=300, predicted heading error", fullPred, "deg", "<", 0.5);
    std::printf("passes with a true error > 1 deg: %d of %d passes (baseline: %d)\n", badPass, passes, badPassLinear);
    report("coverage sweep: passes with a true error > 1 deg, per 1000", 1000.0 * badPass / std::max(passes, 1), "",
           "<=", 2.0);
    report("coverage sweep: predicted/true hard-iron RMS, lowest", worstLow, "", ">=", 0.5);
    report("coverage sweep: predicted/true hard-iron RMS, highest", worstHigh, "", "<=", 2.0);
    report("coverage sweep: true error below the 68 % bound, lowest case", below68Low, "%", ">=", 60);
    report("coverage sweep: true error below the 68 % bound, highest case", below68High, "%", "<=", 76);
    report("coverage sweep: true error below the 95 % bound, lowest case", below95Low, "%", ">=", 90);
}

// The simulated module on a turntable (two turns each way) with a known gyro scale error;
// returns the run's estimate in %, or NaN when the run did not finish.
double gyroScaleEstimate(uint64_t seed, double scaleError)
{
    sim::SimOptions o;
    o.motion = sim::Motion::Turntable;
    o.seed = seed;
    o.gyroScaleError = scaleError;
    sim::HipnucSimulator device(o);
    protocol::StreamDemux demux;
    calib::GyroScaleRun run;
    run.start();
    std::vector<protocol::StreamEvent> events;
    const double endS = 2 * sim::MotionModel::kTurntableStillS + 2 * sim::MotionModel::turntableLegS() + 3.0;
    for (int64_t t = 0; t <= int64_t(endS * 1e6) && run.state() != calib::GyroScaleRun::State::Finished; t += 20000) {
        device.advanceTo(t);
        const std::vector<uint8_t> bytes = device.takeOutput();
        events.clear();
        demux.feed(bytes.data(), bytes.size(), events);
        for (const auto &e : events) {
            protocol::hipnuc::Hi91 f;
            if (e.kind != protocol::StreamEvent::Kind::Frame || !protocol::hipnuc::decodeHi91(e.payload.data(), e.payload.size(), f))
                continue;
            run.addSample(f.systemTime, Vector3d(f.gyr[0], f.gyr[1], f.gyr[2]), Vector3d(f.acc[0], f.acc[1], f.acc[2]));
        }
    }
    const auto r = run.result();
    return r.complete ? r.scaleErrorPct : std::nan("");
}

void gyroScale(uint64_t seed)
{
    constexpr double kTruthPct = 0.5;
    constexpr int kRuns = 5;
    std::printf("Gyro Z scale run in the simulator (turntable 2 x 720 deg, true scale error %.2f %%), %d seeds:\n",
                kTruthPct, kRuns);
    double worst = 0;
    for (int i = 0; i < kRuns; ++i) {
        const double est = gyroScaleEstimate(seed + uint64_t(i), kTruthPct / 100.0);
        std::printf("  seed %llu: estimated %.4f %%\n", static_cast<unsigned long long>(seed + uint64_t(i)), est);
        worst = std::isfinite(est) ? std::max(worst, std::fabs(est - kTruthPct)) : 1e9;
    }
    report("gyro scale run: |estimate - truth| (worst seed)", worst, "%", "<=", 0.06);
}

} // namespace

int main(int argc, char **argv)
{
    int trials = 200;
    int sweepTrials = 400;
    uint64_t seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--trials" && i + 1 < argc) {
            trials = std::atoi(argv[++i]);
        } else if (a == "--sweep-trials" && i + 1 < argc) {
            sweepTrials = std::atoi(argv[++i]);
        } else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 10);
        } else {
            std::fprintf(stderr, "usage: bench_magcal [--trials N (>= 100)] [--sweep-trials N (>= 100)] [--seed N]\n");
            return 2;
        }
    }
    if (trials < 100 || sweepTrials < 100) {
        std::fprintf(stderr, "bench_magcal: --trials and --sweep-trials must be at least 100\n");
        return 2;
    }
    const auto t0 = std::chrono::steady_clock::now();
    magnetometer(seed, trials);
    coverageSweep(seed, sweepTrials);
    gyroScale(seed);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("runtime %.1f s; %s\n", secs, g_failures == 0 ? "all figures met" : "some figures missed");
    return g_failures == 0 ? 0 : 1;
}
