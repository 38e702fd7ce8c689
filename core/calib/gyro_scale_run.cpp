#include "calib/gyro_scale_run.h"

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

namespace {
constexpr double kRadToDeg = 57.29577951308232;
}

GyroScaleRun::GyroScaleRun()
    : GyroScaleRun(Options{})
{
}

GyroScaleRun::GyroScaleRun(Options options)
    : m_options(options),
      m_still(StillnessDetector::Options{std::max(0.2, options.biasWindowS / 2), 0.3, 0.005, 2.0})
{
}

void GyroScaleRun::start()
{
    m_state = State::MeasuringBias;
    m_still.reset();
    m_bias.setZero();
    m_axis = Eigen::Vector3d::UnitZ();
    m_haveLast = false;
    m_angle = m_rate = m_lastRate = 0;
    m_lastMs = m_legStartMs = 0;
    m_belowSinceMs = -1;
    m_paused = false;
    m_firstMs = -1;
    m_samples = 0;
    m_legRates.clear();
    m_legs.clear();
}

bool GyroScaleRun::rateInBand() const
{
    const double r = std::abs(m_rate);
    return r >= m_options.minRateDps && r <= m_options.maxRateDps;
}

GyroScaleRun::State GyroScaleRun::addSample(double timeMs, const Eigen::Vector3d &gyr, const Eigen::Vector3d &acc)
{
    if (m_state == State::Idle || m_state == State::Finished)
        return m_state;
    if (!std::isfinite(timeMs) || !gyr.allFinite() || !acc.allFinite())
        return m_state;
    if (m_haveLast && timeMs <= m_lastMs)
        return m_state; // repeated or older timestamp
    ++m_samples;
    if (m_firstMs < 0)
        m_firstMs = timeMs;

    if (m_state == State::MeasuringBias) {
        m_still.add(timeMs, gyr, acc);
        m_lastMs = timeMs;
        if (m_still.isStill() && m_still.stillForS() >= m_options.biasWindowS) {
            m_bias = m_still.meanGyro();
            const Eigen::Vector3d up = m_still.meanAcc();
            m_axis = up.norm() > 0.5 ? up.normalized() : Eigen::Vector3d::UnitZ();
            m_state = State::WaitingForTurn;
            m_angle = 0;
            m_haveLast = false;
        }
        return m_state;
    }

    const double rate = (gyr - m_bias).dot(m_axis);
    m_rate = rate;
    if (m_haveLast)
        m_angle += 0.5 * (m_lastRate + rate) * (timeMs - m_lastMs) / 1000.0;
    m_lastMs = timeMs;
    m_lastRate = rate;
    m_haveLast = true;

    if (m_state == State::WaitingForTurn) {
        if (std::abs(rate) < m_options.stillRateDps) {
            m_angle = 0; // the leg is integrated from the last still sample
            m_legStartMs = timeMs;
        } else if (std::abs(rate) > m_options.startRateDps) {
            m_state = State::Turning;
            m_legRates.clear();
            m_belowSinceMs = -1;
            m_paused = false;
        }
        return m_state;
    }
    // Turning
    if (m_legRates.size() < kMaxLegSamples)
        m_legRates.emplace_back(timeMs, std::abs(rate));
    if (std::abs(rate) < m_options.stopRateDps) {
        if (m_belowSinceMs < 0)
            m_belowSinceMs = timeMs;
        if (timeMs - m_belowSinceMs >= m_options.stopHoldS * 1000.0) {
            if (std::abs(m_angle) >= m_options.targetDeg - m_options.pauseShortDeg)
                finishLeg();
            else if (std::abs(m_angle) >= m_options.minLegDeg)
                m_paused = true;
            else
                finishLeg(); // a nudge: finishLeg discards it
        }
    } else {
        m_belowSinceMs = -1;
    }
    return m_state;
}

GyroScaleRun::Leg GyroScaleRun::legStats() const
{
    Leg leg;
    leg.angleDeg = m_angle;
    leg.durationS = (m_lastMs - m_legStartMs) / 1000.0;
    leg.stoppedInWindow = std::abs(std::abs(m_angle) - m_options.targetDeg) <= m_options.stopToleranceDeg;
    leg.paused = m_paused;
    if (m_legRates.empty())
        return leg;
    // The even part: the middle 80 % of the time spent turning (before the stop hold).
    const double t0 = m_legRates.front().first;
    const double t1 = m_belowSinceMs > 0 ? m_belowSinceMs : m_legRates.back().first;
    const double lo = t0 + 0.1 * (t1 - t0), hi = t0 + 0.9 * (t1 - t0);
    double sum = 0, sq = 0, mn = 1e300, mx = 0;
    int n = 0, inBand = 0;
    for (const auto &[t, r] : m_legRates) {
        if (t < lo || t > hi)
            continue;
        sum += r;
        sq += r * r;
        mn = std::min(mn, r);
        mx = std::max(mx, r);
        ++n;
        if (r >= m_options.minRateDps && r <= m_options.maxRateDps)
            ++inBand;
    }
    if (n == 0)
        return leg;
    leg.meanRateDps = sum / n;
    leg.minRateDps = mn;
    leg.maxRateDps = mx;
    leg.inBandPct = 100.0 * inBand / n;
    const double var = std::max(0.0, sq / n - leg.meanRateDps * leg.meanRateDps);
    leg.uniformityPct = leg.meanRateDps > 0 ? 100.0 * std::sqrt(var) / leg.meanRateDps : 100.0;
    return leg;
}

void GyroScaleRun::finishLeg()
{
    if (std::abs(m_angle) < m_options.minLegDeg) {
        // A nudge, not a leg: wait for the real turn.
        m_state = State::WaitingForTurn;
        m_angle = 0;
        return;
    }
    m_legs.push_back(legStats());
    m_angle = 0;
    m_legRates.clear();
    m_state = int(m_legs.size()) >= m_options.legs ? State::Finished : State::WaitingForTurn;
}

GyroScaleRun::Result GyroScaleRun::result() const
{
    Result r;
    r.legs = m_legs;
    r.complete = m_state == State::Finished;
    r.biasDps = m_bias.dot(m_axis);
    r.axisTiltDeg = std::acos(std::clamp(m_axis.z(), -1.0, 1.0)) * kRadToDeg;
    if (m_samples > 1 && m_lastMs > m_firstMs)
        r.odrHz = double(m_samples - 1) / ((m_lastMs - m_firstMs) / 1000.0);
    const double target = m_options.targetDeg;
    if (m_legs.size() >= 2 && (m_legs[0].angleDeg > 0) != (m_legs[1].angleDeg > 0)) {
        const double s = m_legs[0].angleDeg > 0 ? 1.0 : -1.0;
        r.scaleErrorPct = 100.0 * ((m_legs[0].angleDeg - m_legs[1].angleDeg) * s / (2 * target) - 1.0);
    } else if (!m_legs.empty()) {
        double sum = 0;
        for (const Leg &l : m_legs)
            sum += std::abs(l.angleDeg);
        r.scaleErrorPct = 100.0 * (sum / (target * double(m_legs.size())) - 1.0);
    }
    QStringList problems;
    for (size_t i = 0; i < m_legs.size(); ++i) {
        const Leg &l = m_legs[i];
        if (!l.stoppedInWindow)
            problems << tr("turn %1 ended at %2 deg, not within %3 deg of %4 deg")
                            .arg(i + 1)
                            .arg(std::abs(l.angleDeg), 0, 'f', 1)
                            .arg(m_options.stopToleranceDeg, 0, 'f', 0)
                            .arg(target, 0, 'f', 0);
        if (l.meanRateDps < m_options.minRateDps || l.meanRateDps > m_options.maxRateDps)
            problems << tr("turn %1 averaged %2 deg/s, outside %3..%4 deg/s")
                            .arg(i + 1)
                            .arg(l.meanRateDps, 0, 'f', 1)
                            .arg(m_options.minRateDps, 0, 'f', 0)
                            .arg(m_options.maxRateDps, 0, 'f', 0);
        if (l.paused)
            problems << tr("turn %1 paused on the way").arg(i + 1);
        if (l.uniformityPct > m_options.maxUniformityPct)
            problems << tr("turn %1 was uneven (rate varied by %2 %)").arg(i + 1).arg(l.uniformityPct, 0, 'f', 0);
    }
    if (r.axisTiltDeg > 3)
        problems << tr("the module is tilted %1 deg: place it level").arg(r.axisTiltDeg, 0, 'f', 1);
    r.acceptable = r.complete && problems.isEmpty();
    if (!r.complete)
        r.summary = tr("Run not finished (%1 of %2 turns done).").arg(m_legs.size()).arg(m_options.legs);
    else if (r.acceptable)
        r.summary = tr("Estimated gyro scale error %1 % (bias %2 deg/s, output rate %3 Hz).")
                        .arg(r.scaleErrorPct, 0, 'f', 3)
                        .arg(r.biasDps, 0, 'f', 3)
                        .arg(r.odrHz, 0, 'f', 1);
    else
        r.summary = tr("Estimated gyro scale error %1 %, but the run was not clean: %2. Repeat it.")
                        .arg(r.scaleErrorPct, 0, 'f', 3)
                        .arg(problems.join(QStringLiteral("; ")));
    return r;
}

QString GyroScaleRun::guidance() const
{
    switch (m_state) {
    case State::Idle:
        return tr("Place the module level on a flat, steady surface, then start.");
    case State::MeasuringBias:
        return tr("Hold the module still (%1 of %2 s).")
            .arg(m_still.stillForS(), 0, 'f', 1)
            .arg(m_options.biasWindowS, 0, 'f', 0);
    case State::WaitingForTurn:
        if (m_legs.empty())
            return tr("Turn the module %1 deg (%2 turns) at an even 20-100 deg/s, in either direction.")
                .arg(m_options.targetDeg, 0, 'f', 0)
                .arg(m_options.targetDeg / 360.0, 0, 'f', 1);
        return tr("Now turn it back the other way, %1 deg, to the same mark.").arg(m_options.targetDeg, 0, 'f', 0);
    case State::Turning: {
        const double left = remainingDeg();
        if (inStopWindow())
            return tr("Stop now: on the mark.");
        if (left < 0)
            return tr("Too far: %1 deg past the target. Stop and repeat the run.").arg(-left, 0, 'f', 0);
        if (std::abs(m_rate) < m_options.minRateDps)
            return tr("Keep turning, a little faster: %1 deg to go.").arg(left, 0, 'f', 0);
        if (std::abs(m_rate) > m_options.maxRateDps)
            return tr("Keep turning, a little slower: %1 deg to go.").arg(left, 0, 'f', 0);
        return tr("Keep turning evenly: %1 deg to go.").arg(left, 0, 'f', 0);
    }
    case State::Finished:
        return result().summary;
    }
    return {};
}

} // namespace imudesk::calib
