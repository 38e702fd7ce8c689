#include "compass_check.h"
#include "check_steps.h"

#include "model/attitude.h"

#include <algorithm>
#include <cmath>

namespace imudesk::verify {

namespace {

constexpr double kPi = 3.141592653589793;

// Circular mean of headings (deg, 0..360).
double meanHeading(const std::vector<CompassSample> &s, size_t a, size_t b)
{
    double sx = 0, sy = 0;
    for (size_t i = a; i < b; ++i) {
        sx += std::sin(s[i].headingDeg * kPi / 180);
        sy += std::cos(s[i].headingDeg * kPi / 180);
    }
    const double h = std::atan2(sx, sy) * 180 / kPi;
    return h < 0 ? h + 360 : h;
}

double spreadAbout(const std::vector<CompassSample> &s, size_t a, size_t b, double mean)
{
    double sq = 0;
    for (size_t i = a; i < b; ++i) {
        const double d = model::wrap180(s[i].headingDeg - mean);
        sq += d * d;
    }
    return std::sqrt(sq / double(std::max<size_t>(1, b - a)));
}

// pass / warn / fail of one figure (as the module check's).
Verdict judge(const Figure &f, const Limit &limit)
{
    const double bound = f.bound95();
    if (std::fabs(f.value) + bound <= limit.pass)
        return Verdict::Pass;
    if (std::fabs(f.value) - bound > limit.fail)
        return Verdict::Fail;
    return Verdict::Warn;
}

} // namespace

CompassReport checkCompass(const std::vector<CompassSample> &samples, const CompassCheckOptions &options)
{
    CompassReport r;
    const size_t n = samples.size();
    // Stops: the longest runs over which a window of minHoldS stays steady.
    for (size_t i = 0; i < n;) {
        size_t j = i;
        while (j < n && samples[j].tS - samples[i].tS < options.minHoldS)
            ++j;
        if (j >= n)
            break;
        double mean = meanHeading(samples, i, j + 1);
        if (spreadAbout(samples, i, j + 1, mean) > options.maxHeadingSpreadDeg) {
            ++i;
            continue;
        }
        // Grow the stop while the heading stays within three spreads of its mean.
        while (j + 1 < n && std::fabs(model::wrap180(samples[j + 1].headingDeg - mean)) <= 3 * options.maxHeadingSpreadDeg)
            ++j;
        mean = meanHeading(samples, i, j + 1);
        CompassStop stop;
        stop.fromS = samples[i].tS;
        stop.toS = samples[j].tS;
        stop.headingDeg = mean;
        const size_t count = j + 1 - i;
        stop.headingSigmaDeg = std::max(0.05, spreadAbout(samples, i, j + 1, mean)) / std::sqrt(double(count));
        for (size_t k = i; k <= j; ++k) {
            stop.pitchDeg += samples[k].pitchDeg / double(count);
            stop.rollDeg += samples[k].rollDeg / double(count);
        }
        double nearest = options.matchToleranceDeg;
        for (size_t b = 0; b < options.bearingsDeg.size(); ++b)
            if (const double d = std::fabs(model::wrap180(mean - options.bearingsDeg[b])); d <= nearest) {
                nearest = d;
                stop.bearing = int(b);
            }
        if (stop.bearing >= 0)
            stop.errorDeg = model::wrap180(mean - options.bearingsDeg[size_t(stop.bearing)]);
        r.stops.push_back(stop);
        i = j + 1;
    }
    // One figure per bearing: its longest stop.
    std::vector<const CompassStop *> best(options.bearingsDeg.size(), nullptr);
    for (const CompassStop &s : r.stops)
        if (s.bearing >= 0 && (!best[size_t(s.bearing)] || s.toS - s.fromS > best[size_t(s.bearing)]->toS - best[size_t(s.bearing)]->fromS))
            best[size_t(s.bearing)] = &s;
    QStringList missing;
    std::vector<const CompassStop *> held;
    for (size_t b = 0; b < best.size(); ++b) {
        if (best[b])
            held.push_back(best[b]);
        else
            missing << QString::number(options.bearingsDeg[b]);
    }
    r.bearingsHeld = int(held.size());
    if (!missing.isEmpty() || held.size() < 2) {
        const QString why = CheckReport::tr("the compass was not held still for %1 s at the bearings %2°: turn it to each "
                                            "marked bearing of a level compass rose and hold it there")
                                .arg(options.minHoldS)
                                .arg(missing.isEmpty() ? QStringLiteral("(none marked)") : missing.join(QStringLiteral("°, ")));
        r.worstHeadingErrDeg.why = r.meanHeadingErrDeg.why = r.pitchErrDeg.why = r.rollErrDeg.why = why;
        r.reasons << CheckReport::tr("heading error: cannot judge, %1").arg(why);
        return r;
    }
    const CompassStop *worst = held.front();
    double meanErr = 0, meanPitch = 0, meanRoll = 0;
    for (const CompassStop *s : held) {
        if (std::fabs(s->errorDeg) > std::fabs(worst->errorDeg))
            worst = s;
        meanErr += s->errorDeg / double(held.size());
        meanPitch += s->pitchDeg / double(held.size());
        meanRoll += s->rollDeg / double(held.size());
    }
    auto spreadOf = [&held](auto value, double mean) {
        double sq = 0;
        for (const CompassStop *s : held)
            sq += std::pow(value(*s) - mean, 2);
        return std::sqrt(sq / double(held.size() - 1) / double(held.size())) * smallSampleFactor(int(held.size()) - 1);
    };
    r.worstHeadingErrDeg = Figure{true, worst->errorDeg, worst->headingSigmaDeg, {}};
    r.worstBearingDeg = options.bearingsDeg[size_t(worst->bearing)];
    r.meanHeadingErrDeg = Figure{true, meanErr, spreadOf([](const CompassStop &s) { return s.errorDeg; }, meanErr), {}};
    r.pitchErrDeg = Figure{true, meanPitch, spreadOf([](const CompassStop &s) { return s.pitchDeg; }, meanPitch), {}};
    r.rollErrDeg = Figure{true, meanRoll, spreadOf([](const CompassStop &s) { return s.rollDeg; }, meanRoll), {}};

    struct Judged {
        Verdict v;
        QString text;
    };
    std::vector<Judged> judged;
    auto add = [&](const QString &what, const Figure &f, const Limit &limit) {
        const Verdict v = judge(f, limit);
        judged.push_back({v, CheckReport::tr("%1: %2 ± %3 ° (95 %), pass at most %4, fail above %5: %6")
                                 .arg(what)
                                 .arg(f.value, 0, 'f', 2)
                                 .arg(f.bound95(), 0, 'f', 2)
                                 .arg(limit.pass)
                                 .arg(limit.fail)
                                 .arg(verdictText(v))});
    };
    add(CheckReport::tr("heading error at %1°, the worst bearing").arg(r.worstBearingDeg), r.worstHeadingErrDeg,
        options.headingDeg);
    add(CheckReport::tr("heading offset, mean of the bearings"), r.meanHeadingErrDeg, options.headingDeg);
    add(CheckReport::tr("pitch on the level rose"), r.pitchErrDeg, options.tiltDeg);
    add(CheckReport::tr("roll on the level rose"), r.rollErrDeg, options.tiltDeg);
    auto rank = [](Verdict v) { return v == Verdict::Fail ? 2 : v == Verdict::Warn ? 1 : 0; };
    std::stable_sort(judged.begin(), judged.end(), [&](const Judged &a, const Judged &b) { return rank(a.v) > rank(b.v); });
    r.verdict = judged.front().v;
    for (const Judged &j : judged)
        r.reasons << j.text;
    return r;
}

} // namespace imudesk::verify
