#include "calib/heading_check.h"

#include "model/sample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace imudesk::calib {

namespace {
constexpr double kCheckDeg = std::numbers::pi / 180.0;
// Samples further apart than this (s) are not compared: a gap in the output, not a step.
constexpr double kHeadingCompareGapS = 0.5;

double headingStep180(double d)
{
    while (d > 180.0)
        d -= 360.0;
    while (d < -180.0)
        d += 360.0;
    return d;
}
} // namespace

void HeadingCheck::reset()
{
    const auto hardIron = m_hardIron;
    const Eigen::Matrix3d softIron = m_softIron;
    *this = HeadingCheck();
    m_hardIron = hardIron;
    m_softIron = softIron;
}

void HeadingCheck::setFieldCorrection(const Eigen::Vector3d &hardIron, const Eigen::Matrix3d &softIron)
{
    m_hardIron = hardIron;
    m_softIron = softIron;
    m_levelFields.clear();
    m_referenceField = 0;
}

void HeadingCheck::clearFieldCorrection()
{
    m_hardIron.reset();
    m_levelFields.clear();
    m_referenceField = 0;
    m_disturbed = false;
}

void HeadingCheck::add(const model::Sample &s)
{
    if (!s.has(model::FieldEuler) || !std::isfinite(s.yaw) || !std::isfinite(s.roll) || !std::isfinite(s.pitch))
        return;
    const double timeS = s.has(model::FieldDeviceTime) && std::isfinite(s.deviceTimeMs) ? s.deviceTimeMs / 1e3
                                                                                         : double(s.hostTimeNs) / 1e9;
    // The tilt of the body's z axis from the vertical (ENU-312: cos tilt = cos roll cos pitch).
    m_tilt = std::acos(std::clamp(std::cos(s.roll * kCheckDeg) * std::cos(s.pitch * kCheckDeg), -1.0, 1.0)) / kCheckDeg;
    m_largestTilt = std::max(m_largestTilt, m_tilt);
    m_tilted = m_tilt > kMaxTiltDeg;

    // The field, corrected, against the median of the level turn so far.
    m_disturbed = false;
    m_fieldChangePct = std::numeric_limits<double>::quiet_NaN();
    if (m_hardIron && s.has(model::FieldMag)) {
        const Eigen::Vector3d m(s.mag.x, s.mag.y, s.mag.z);
        const double field = (m_softIron * (m - *m_hardIron)).norm();
        if (std::isfinite(field) && field > 0) {
            if (m_referenceField > 0) {
                m_fieldChangePct = 100.0 * (field - m_referenceField) / m_referenceField;
                m_disturbed = std::abs(m_fieldChangePct) > kMaxFieldChangePct;
            }
            if (!m_tilted && !m_disturbed) {
                m_levelFields.push_back(field);
                if (m_levelFields.size() >= size_t(kFieldReferenceSamples)
                    && (m_referenceField <= 0 || m_levelFields.size() % 25 == 0)) {
                    std::vector<double> sorted = m_levelFields;
                    auto mid = sorted.begin() + std::ptrdiff_t(sorted.size() / 2);
                    std::nth_element(sorted.begin(), mid, sorted.end());
                    m_referenceField = *mid;
                }
            }
        }
    }
    const bool judgeable = !m_tilted && !m_disturbed;

    if (m_haveLast) {
        const double dt = timeS - m_lastTimeS;
        const double step = headingStep180(s.yaw - m_lastYaw);
        m_totalTurn += std::abs(step);
        if (dt >= 0 && dt <= kHeadingCompareGapS) {
            // What the gyro turned about the vertical meanwhile (ENU-312: the vertical component
            // of the body rate is -cos(pitch) sin(roll) wx + sin(pitch) wy + cos(pitch) cos(roll) wz).
            // Taken only where it makes the step smaller, so a device whose Euler angles count
            // the other way round is judged on the step alone.
            double beyond = std::abs(step);
            if (s.has(model::FieldGyr)) {
                const double cr = std::cos(s.roll * kCheckDeg), sr = std::sin(s.roll * kCheckDeg);
                const double cp = std::cos(s.pitch * kCheckDeg), sp = std::sin(s.pitch * kCheckDeg);
                const double up = -cp * sr * s.gyr.x + sp * s.gyr.y + cp * cr * s.gyr.z;
                if (std::isfinite(up))
                    beyond = std::min(beyond, std::abs(step - up * dt));
            }
            if (judgeable && m_lastJudgeable) {
                m_levelTurn += std::abs(step);
                m_largestJudgedStep = std::max(m_largestJudgedStep, beyond);
                if (beyond > kMaxJumpDeg && !passed())
                    m_jumped = true;
            } else if (beyond > kMaxJumpDeg) {
                ++m_unjudgedJumps;
            }
        }
    }
    m_haveLast = true;
    m_lastYaw = s.yaw;
    m_lastTimeS = timeS;
    m_lastJudgeable = judgeable;
}

HeadingCheck::Status HeadingCheck::status() const
{
    if (m_jumped)
        return Status::Jumps;
    if (m_levelTurn >= kFullTurnDeg)
        return Status::Passed;
    if (m_tilted)
        return Status::Tilted;
    if (m_disturbed)
        return Status::FieldDisturbed;
    return Status::TurnMore;
}

QString HeadingCheck::advice() const
{
    switch (status()) {
    case Status::Passed:
        return tr("Passed: %1 deg turned level, the heading followed without a jump (largest step %2 deg).")
            .arg(m_levelTurn, 0, 'f', 0)
            .arg(m_largestJudgedStep, 0, 'f', 1);
    case Status::Jumps:
        return tr("The heading jumped by %1 deg while the module was level and the field steady: the heading does "
                  "not follow the calibration. Calibrate again (chapter 9.31).")
            .arg(m_largestJudgedStep, 0, 'f', 1);
    case Status::Tilted:
        return tr("Keep the module level while you turn it: it is tilted by %1 deg, at most %2 deg is judged. The "
                  "heading of a tilted module also moves with the tilt, so the check cannot judge it (%3 of %4 deg "
                  "turned level so far).")
            .arg(m_tilt, 0, 'f', 0)
            .arg(kMaxTiltDeg, 0, 'f', 0)
            .arg(m_levelTurn, 0, 'f', 0)
            .arg(kFullTurnDeg, 0, 'f', 0);
    case Status::FieldDisturbed:
        return tr("The field is disturbed here (|B| %1 % off the level turn's): iron, a magnet or a current nearby. "
                  "The check cannot judge the heading in a disturbed field; move away from it and turn on.")
            .arg(m_fieldChangePct, 0, 'f', 0);
    case Status::TurnMore:
        break;
    }
    return tr("Keep turning, level and slowly: %1 of %2 deg turned.").arg(m_levelTurn, 0, 'f', 0).arg(kFullTurnDeg, 0, 'f', 0);
}

} // namespace imudesk::calib
