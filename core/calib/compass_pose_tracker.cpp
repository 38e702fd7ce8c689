#include "calib/compass_pose_tracker.h"

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

namespace {

double headingDiff(double a, double b)
{
    double d = std::fmod(std::fabs(a - b), 360.0);
    return d > 180.0 ? 360.0 - d : d;
}

std::vector<PoseTarget> twelvePoint(bool smallTilt)
{
    // HEC495 manual, tables of "自动 12 方位校准" and "自动 12 方位小倾斜校准".
    static const double headings[12] = {0, 90, 180, 270, 30, 120, 210, 300, 60, 150, 240, 330};
    std::vector<PoseTarget> t;
    for (int i = 0; i < 12; ++i) {
        PoseTarget p;
        p.number = i + 1;
        p.headingDeg = headings[i];
        if (i < 4) {
            p.pitchMinDeg = -5;
            p.pitchMaxDeg = 5;
        } else if (i < 8) {
            p.pitchMinDeg = 45;
            p.pitchMaxDeg = 90;
        } else {
            p.pitchMinDeg = -90;
            p.pitchMaxDeg = -45;
        }
        if (smallTilt) {
            p.rollMinDeg = -5;
            p.rollMaxDeg = 5;
        } else if (i % 2 == 0) {
            p.rollMinDeg = 30;
            p.rollMaxDeg = 40;
        } else {
            p.rollMinDeg = -40;
            p.rollMaxDeg = -30;
        }
        t.push_back(p);
    }
    return t;
}

} // namespace

std::vector<PoseTarget> CompassPoseTracker::targets(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::Auto12: return twelvePoint(false);
    case CompassCalMethod::Auto12SmallTilt: return twelvePoint(true);
    case CompassCalMethod::Planar: {
        std::vector<PoseTarget> t;
        for (int i = 0; i < 12; ++i)
            t.push_back(PoseTarget{i + 1, 30.0 * i, -2, 2, -2, 2});
        return t;
    }
    case CompassCalMethod::Manual:
    case CompassCalMethod::AutoAllOrientation: return {};
    }
    return {};
}

int CompassPoseTracker::maxPoints(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::AutoAllOrientation: return 96;
    case CompassCalMethod::Manual: return 0;
    default: return 12;
    }
}

int CompassPoseTracker::minPoints(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::Manual: return 12;
    case CompassCalMethod::AutoAllOrientation: return 12;
    default: return 12;
    }
}

uint8_t CompassPoseTracker::startCommandCode(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::Auto12: return 0x63;
    case CompassCalMethod::Manual: return 0x65;
    case CompassCalMethod::AutoAllOrientation: return 0x08;
    case CompassCalMethod::Auto12SmallTilt: return 0x64;
    case CompassCalMethod::Planar: return 0x60;
    }
    return 0x63;
}

QString CompassPoseTracker::methodName(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::Auto12: return tr("Automatic 12-point");
    case CompassCalMethod::Manual: return tr("Manual");
    case CompassCalMethod::AutoAllOrientation: return tr("Automatic all-orientation");
    case CompassCalMethod::Auto12SmallTilt: return tr("12-point small tilt");
    case CompassCalMethod::Planar: return tr("Planar");
    }
    return {};
}

QString CompassPoseTracker::instructions(CompassCalMethod m)
{
    switch (m) {
    case CompassCalMethod::Auto12:
        return tr("Turn the compass, together with everything mounted with it, to each of the 12 poses shown; it "
                  "collects a point by itself near each one. Needs pitch beyond 45 deg and roll beyond 30 deg.");
    case CompassCalMethod::Manual:
        return tr("Turn the compass to the poses it will be used in and collect a point at each (at least 12); "
                  "spread the headings evenly.");
    case CompassCalMethod::AutoAllOrientation:
        return tr("Start level. Turn 2-3 times about the vertical axis (10-15 s per turn, speeding up and slowing "
                  "down), then 1-2 times about X and Y (about 10 s per turn), then at random so that every "
                  "orientation is reached. Up to 96 points.");
    case CompassCalMethod::Auto12SmallTilt:
        return tr("For roll below 5 deg: keep it nearly level in roll and turn to the 12 headings and pitches "
                  "shown (pitch beyond 45 deg).");
    case CompassCalMethod::Planar:
        return tr("Place the compass level (pitch and roll below 2 deg) and turn it one full circle slowly and "
                  "evenly. Up to 12 points.");
    }
    return {};
}

CompassPoseTracker::CompassPoseTracker(CompassCalMethod method, double headingToleranceDeg, double rangeMarginDeg)
    : m_method(method),
      m_headingTol(headingToleranceDeg),
      m_margin(rangeMarginDeg),
      m_targets(targets(method)),
      m_collected(m_targets.size(), false)
{
}

void CompassPoseTracker::clear()
{
    std::fill(m_collected.begin(), m_collected.end(), false);
    m_validPoints = 0;
    m_current = -1;
}

bool CompassPoseTracker::matches(const PoseTarget &t, double heading, double pitch, double roll) const
{
    return headingDiff(heading, t.headingDeg) <= m_headingTol && pitch >= t.pitchMinDeg - m_margin
        && pitch <= t.pitchMaxDeg + m_margin && roll >= t.rollMinDeg - m_margin && roll <= t.rollMaxDeg + m_margin;
}

int CompassPoseTracker::updatePose(double heading, double pitch, double roll)
{
    m_current = -1;
    if (!std::isfinite(heading) || !std::isfinite(pitch) || !std::isfinite(roll))
        return -1;
    // Prefer a target not yet collected when two overlap.
    for (int pass = 0; pass < 2 && m_current < 0; ++pass)
        for (size_t i = 0; i < m_targets.size(); ++i)
            if ((pass == 1 || !m_collected[i]) && matches(m_targets[i], heading, pitch, roll)) {
                m_current = int(i);
                break;
            }
    return m_current;
}

int CompassPoseTracker::setValidPoints(int count)
{
    if (count < 0)
        return -1;
    if (count < m_validPoints) {
        // The device started over (stop/clear or a new run).
        clear();
    }
    int lit = -1;
    if (count > m_validPoints && m_current >= 0 && !m_collected[size_t(m_current)]) {
        m_collected[size_t(m_current)] = true;
        lit = m_current;
    }
    m_validPoints = count;
    return lit;
}

bool CompassPoseTracker::collected(int index) const
{
    return index >= 0 && size_t(index) < m_collected.size() && m_collected[size_t(index)];
}

int CompassPoseTracker::collectedCount() const
{
    return int(std::count(m_collected.begin(), m_collected.end(), true));
}

double CompassPoseTracker::progressPct() const
{
    const int max = maxPoints(m_method) > 0 ? maxPoints(m_method) : minPoints(m_method);
    return std::min(100.0, 100.0 * m_validPoints / max);
}

QString CompassPoseTracker::nextHint() const
{
    if (m_targets.empty()) {
        if (m_validPoints < minPoints(m_method))
            return tr("%1 points collected, at least %2 needed.").arg(m_validPoints).arg(minPoints(m_method));
        return tr("%1 points collected: you can save the calibration.").arg(m_validPoints);
    }
    for (size_t i = 0; i < m_targets.size(); ++i) {
        if (m_collected[i])
            continue;
        const PoseTarget &t = m_targets[i];
        return tr("Point %1: heading %2 deg, pitch %3..%4 deg, roll %5..%6 deg")
            .arg(t.number)
            .arg(t.headingDeg, 0, 'f', 0)
            .arg(t.pitchMinDeg, 0, 'f', 0)
            .arg(t.pitchMaxDeg, 0, 'f', 0)
            .arg(t.rollMinDeg, 0, 'f', 0)
            .arg(t.rollMaxDeg, 0, 'f', 0);
    }
    return tr("All %1 points collected: save the calibration.").arg(m_targets.size());
}

} // namespace imudesk::calib
