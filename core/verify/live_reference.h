#pragma once
// ImuDesk's reference attitude of a live module (issue 55: the 3D view's ghost): the reference
// filter (reference_filter.h) on the module's raw gyro and accelerometer as they arrive. It
// starts once the module has rested kRestS: the gyro's bias from that rest, the tilt from the
// accelerometer, the heading from the module's own (a magnetometer that was never checked is
// no reference for north); from then on gravity corrects the tilt whenever the module rests or
// moves gently, and the heading follows the gyro alone. So the ghost shows where the module's
// filter and ImuDesk's part: a tilt that is off, a heading that drifts or jumps, a lag. The
// samples followed are those of the first frame type with both an accelerometer and a gyro.
// Bounded: a window of kRestS of samples.
#include "verify/module_check.h"
#include "verify/reference_filter.h"

#include "model/sample.h"

#include <deque>
#include <memory>
#include <string>

namespace imudesk::verify {

class LiveReference {
public:
    static constexpr double kRestS = 1.0;

    void add(const model::Sample &s);
    void reset();
    bool started() const { return m_filter != nullptr; }
    // Body to ENU; identity before the start.
    Eigen::Quaterniond attitude() const;
    double sigmaDeg() const;
    // The angle between a reported attitude and the reference (deg), when started.
    double differenceDeg(const Eigen::Quaterniond &reported) const;

private:
    struct Rest {
        double tS;
        Eigen::Vector3d acc, gyr;
    };
    std::string m_source;
    std::deque<Rest> m_window;
    std::unique_ptr<ReferenceFilter> m_filter;
};

} // namespace imudesk::verify
