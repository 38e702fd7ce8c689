// bench_verify: the module check (core/verify, issue 55) against simulated modules whose
// errors are known.
//
// --modules N (200) modules, each with random errors drawn from its seed: accelerometer bias
// ±30 mg, scale ±1.5 % and misalignment ±0.5° per axis, gyro scale ±1 % and misalignment ±0.5° per axis, an attitude
// off by ±0.5° in roll and pitch and ±3° in heading and late by 0..80 ms; each turned by hand through 12 poses
// (sim::Motion::Poses: unequal holds, jerky moves, one pose held too briefly) at 400 Hz, its
// magnetometer as an MCAL left it (2 % of its iron). Printed with their targets:
//   * p95 of |recovered - injected|: accelerometer bias <= 1 mg, scale <= 0.05 %, gyro scale
//     <= 0.1 %, tilt (roll, pitch) <= 0.05°, heading <= 0.3°;
//   * the bounds: the truth inside the 68 % bound in 60-76 % and inside the 95 % bound in at
//     least 90 % of the figures, per kind of figure;
//   * no module with a 3° heading bias or a 1 % accelerometer scale error passes with the
//     default limits (--wrong N modules of each);
//   * the lag of the module's attitude (0..80 ms injected) against ImuDesk's reference filter:
//     p95 of the error <= 5 ms;
//   * 15 minutes of a 400 Hz recording analysed in at most 2 s;
//   * beside the tilt figure, the baseline: the same poses with the uncalibrated
//     accelerometer as the tilt reference (what a check without the multi-position fit sees).
//
//   bench_verify [--modules N] [--wrong N]
// Exit status 1 when a target is missed, 2 on bad arguments.
#include "../common/verify_rig.h"
#include "verify/check_steps.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace imudesk;

namespace {

double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return NAN;
    std::sort(v.begin(), v.end());
    const size_t k = std::min(v.size() - 1, size_t(std::ceil(p * double(v.size()))) - 1);
    return v[k];
}

struct Coverage {
    int n = 0, in68 = 0, in95 = 0;
    void add(double error, double sigma)
    {
        ++n;
        in68 += std::fabs(error) <= sigma;
        in95 += std::fabs(error) <= 1.959964 * sigma;
    }
    double share68() const { return n ? 100.0 * in68 / n : NAN; }
    double share95() const { return n ? 100.0 * in95 / n : NAN; }
};

bool failed = false;

void target(const char *what, double value, const char *unit, double goal, bool atMost = true, const char *beside = "")
{
    const bool ok = atMost ? value <= goal : value >= goal;
    failed = failed || !ok;
    std::printf("  %-52s %10.4f %-4s target %s %.4f  %s%s\n", what, value, unit, atMost ? "<=" : ">=", goal,
                ok ? "PASS" : "FAIL", beside);
}

void coverageTarget(const char *what, const Coverage &c)
{
    const bool ok = c.share68() >= 60 && c.share68() <= 76 && c.share95() >= 90;
    failed = failed || !ok;
    std::printf("  %-40s n=%4d  inside 68 %%: %5.1f %% (60-76)  inside 95 %%: %5.1f %% (>= 90)  %s\n", what, c.n, c.share68(),
                c.share95(), ok ? "PASS" : "FAIL");
}

test::HandTurnedModule randomModule(uint64_t seed)
{
    std::mt19937_64 g(seed * 7919 + 17);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    test::HandTurnedModule m;
    m.seed = seed;
    for (int a = 0; a < 3; ++a) {
        m.accError.biasG[a] = 0.030 * u(g);
        m.accError.scale[a] = 0.015 * u(g);
        m.accError.misalignmentRad[a] = 0.5 * u(g) * M_PI / 180;
        m.gyroScale[a] = 0.01 * u(g);
        m.gyroMisalignment[a] = 0.5 * u(g) * M_PI / 180;
    }
    m.attitudeBiasDeg = {0.5 * u(g), 0.5 * u(g), 3.0 * u(g)};
    m.lagMs = 40.0 + 40.0 * u(g);
    return m;
}

} // namespace

int main(int argc, char **argv)
{
    int modules = 200, wrong = 50;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--modules") && i + 1 < argc)
            modules = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--wrong") && i + 1 < argc)
            wrong = std::atoi(argv[++i]);
        else {
            std::fprintf(stderr, "usage: bench_verify [--modules N] [--wrong N]\n");
            return 2;
        }
    }
    if (modules < 10 || wrong < 1) {
        std::fprintf(stderr, "bench_verify: --modules needs at least 10, --wrong at least 1\n");
        return 2;
    }
    verify::CheckOptions options;
    options.gravityMs2 = model::kGravity; // the simulator's gravity is the module's 1 G

    std::vector<double> biasErr, scaleErr, misErr, gyroErr, gyroMisErr, tiltErr, headingErr, baselineTiltErr, lagErr;
    Coverage covBias, covScale, covMis, covGyro, covGyroMis, covTilt, covHeading;
    int judgedAll = 0;
    for (int k = 0; k < modules; ++k) {
        const test::HandTurnedModule m = randomModule(uint64_t(1000 + k));
        const auto samples = m.record();
        const verify::CheckReport r = verify::checkModule(samples, options);
        if (!r.accBiasMg.judged || !r.gyroScalePct.judged || !r.rollErrDeg.judged || !r.headingErrDeg.judged
            || !r.dynamicLagMs.judged) {
            std::printf("  module %d: not every figure judged (%s)\n", k,
                        qPrintable(r.reasons.filter(QStringLiteral("cannot judge")).join(QStringLiteral("; "))));
            continue;
        }
        ++judgedAll;
        Eigen::Vector3d scaleTruth, misTruth;
        verify::accFiguresOf(m.accError.matrix(), scaleTruth, misTruth);
        Eigen::Vector3d gyroScaleTruth, gyroMisTruth;
        {
            sim::SensorModel gyro(m.seed);
            gyro.setGyroScaleErrors(m.gyroScale);
            gyro.setGyroMisalignment(m.gyroMisalignment);
            verify::accFiguresOf(gyro.gyroMatrix(), gyroScaleTruth, gyroMisTruth);
        }
        if (r.gyroMisalignmentDeg.judged)
            for (int a = 0; a < 3; ++a) {
                gyroMisErr.push_back(std::fabs(r.gyroMisalignmentAxesDeg[a] - gyroMisTruth[a]));
                covGyroMis.add(r.gyroMisalignmentAxesDeg[a] - gyroMisTruth[a], r.gyroMisalignmentAxesSigmaDeg[a]);
            }
        for (int a = 0; a < 3; ++a) {
            const double eb = r.accBiasMg.value[a] - m.accError.biasG[a] * 1000;
            const double es = r.accScalePct.value[a] - scaleTruth[a];
            const double em = r.accMisalignmentAxesDeg[a] - misTruth[a];
            const double eg = r.gyroScalePct.value[a] - gyroScaleTruth[a];
            biasErr.push_back(std::fabs(eb));
            scaleErr.push_back(std::fabs(es));
            misErr.push_back(std::fabs(em));
            gyroErr.push_back(std::fabs(eg));
            covBias.add(eb, r.accBiasMg.sigma[a]);
            covScale.add(es, r.accScalePct.sigma[a]);
            covGyro.add(eg, r.gyroScalePct.sigma[a]);
        }
        for (int a = 0; a < 3; ++a)
            covMis.add(r.accMisalignmentAxesDeg[a] - misTruth[a], r.accMisalignmentAxesSigmaDeg[a]);
        const double er = r.rollErrDeg.value - m.attitudeBiasDeg[0];
        const double ep = r.pitchErrDeg.value - m.attitudeBiasDeg[1];
        const double eh = r.headingErrDeg.value - m.attitudeBiasDeg[2];
        tiltErr.push_back(std::fabs(er));
        tiltErr.push_back(std::fabs(ep));
        headingErr.push_back(std::fabs(eh));
        covTilt.add(er, r.rollErrDeg.sigma);
        covTilt.add(ep, r.pitchErrDeg.sigma);
        covHeading.add(eh, r.headingErrDeg.sigma);
        lagErr.push_back(std::fabs(r.dynamicLagMs.value - m.lagMs));

        // The baseline: the same poses, the raw accelerometer as the tilt reference.
        std::vector<verify::Pose> poses = r.poses;
        verify::AccFit raw;
        raw.ok = true;
        const verify::AttitudeCheck base = verify::checkAttitude(poses, raw, options);
        if (base.roll.judged) {
            baselineTiltErr.push_back(std::fabs(base.roll.value - m.attitudeBiasDeg[0]));
            baselineTiltErr.push_back(std::fabs(base.pitch.value - m.attitudeBiasDeg[1]));
        }
    }
    std::printf("bench_verify: %d simulated modules, 12 poses each by hand at 400 Hz; %d with every figure judged\n",
                modules, judgedAll);
    target("modules with every figure judged (%)", 100.0 * judgedAll / modules, "%", 95, false);
    std::printf("recovered against injected (p95):\n");
    target("accelerometer bias", percentile(biasErr, 0.95), "mg", 1.0);
    target("accelerometer scale", percentile(scaleErr, 0.95), "%", 0.05);
    std::printf("  %-52s %10.4f %-4s (printed)\n", "accelerometer misalignment", percentile(misErr, 0.95), "deg");
    target("gyro scale", percentile(gyroErr, 0.95), "%", 0.1);
    std::printf("  %-52s %10.4f %-4s (printed; %zu of %d modules judged)\n", "gyro misalignment", percentile(gyroMisErr, 0.95),
                "deg", gyroMisErr.size() / 3, judgedAll);
    char beside[96];
    std::snprintf(beside, sizeof beside, "   baseline (raw accelerometer as reference): %.4f deg",
                  percentile(baselineTiltErr, 0.95));
    target("tilt (roll and pitch)", percentile(tiltErr, 0.95), "deg", 0.05, true, beside);
    target("heading", percentile(headingErr, 0.95), "deg", 0.3);
    target("attitude lag while moving (0..80 ms injected)", percentile(lagErr, 0.95), "ms", 5.0);
    std::printf("bounds (the truth inside the figure's 68 %% and 95 %% bounds):\n");
    coverageTarget("accelerometer bias", covBias);
    coverageTarget("accelerometer scale", covScale);
    coverageTarget("accelerometer misalignment", covMis);
    coverageTarget("gyro scale", covGyro);
    coverageTarget("gyro misalignment", covGyroMis);
    coverageTarget("tilt", covTilt);
    coverageTarget("heading", covHeading);

    std::printf("wrong modules with the default limits (%d each):\n", wrong);
    int passedHeading = 0, passedScale = 0;
    for (int k = 0; k < wrong; ++k) {
        test::HandTurnedModule h;
        h.seed = uint64_t(5000 + k);
        h.attitudeBiasDeg = {0, 0, k % 2 ? 3.0 : -3.0};
        passedHeading += verify::checkModule(h.record(), options).verdict == verify::Verdict::Pass;
        test::HandTurnedModule s;
        s.seed = uint64_t(6000 + k);
        s.accError.scale = Eigen::Vector3d::Constant(k % 2 ? 0.01 : -0.01);
        passedScale += verify::checkModule(s.record(), options).verdict == verify::Verdict::Pass;
    }
    target("3 deg heading bias: modules that pass", passedHeading, "", 0);
    target("1 % accelerometer scale error: modules that pass", passedScale, "", 0);

    // 15 minutes at 400 Hz: the poses, then the module left on the table.
    test::HandTurnedModule longRun;
    longRun.seed = 77;
    const sim::MotionModel motion(sim::MotionModel::Options{77, sim::Motion::Poses});
    longRun.tailS = 900 - motion.posesEndS();
    const auto samples = longRun.record();
    const auto t0 = std::chrono::steady_clock::now();
    const verify::CheckReport r = verify::checkModule(samples, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("15 minutes at 400 Hz (%zu samples, verdict %s):\n", samples.size(), verify::verdictName(r.verdict));
    target("analysis time", seconds, "s", 2.0);
    return failed ? 1 : 0;
}
