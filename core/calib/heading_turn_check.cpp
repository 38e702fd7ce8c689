#include "calib/heading_turn_check.h"

#include <algorithm>
#include <cmath>

namespace imudesk::calib {

void HeadingTurnCheck::reset()
{
    *this = HeadingTurnCheck();
}

void HeadingTurnCheck::add(double headingDeg)
{
    if (!std::isfinite(headingDeg))
        return;
    ++m_samples;
    if (m_have) {
        // The shortest way from the last heading: a step across +-180 (or 0/360) is a small one.
        const double d = std::abs(std::remainder(headingDeg - m_last, 360.0));
        m_turned += d;
        m_maxJump = std::max(m_maxJump, d);
    }
    m_last = headingDeg;
    m_have = true;
}

HeadingTurnCheck::Verdict HeadingTurnCheck::verdict() const
{
    if (m_maxJump > kMaxJumpDeg)
        return Verdict::Jumped;
    return m_turned >= kTurnDeg ? Verdict::Passed : Verdict::KeepTurning;
}

} // namespace imudesk::calib
