#pragma once
// The module check's input from decoded samples (a file's or a live session's): the samples of
// the first frame type that carries both the accelerometer and the gyro (a module sending HI91
// and HI83 gives one series, not two interleaved), on the module's own clock where the frame
// has one (HI91 system_time), else on their arrival; the attitude from the quaternion, else
// from the Euler angles (ENU 3-1-2). Bounded: kMaxSamples (an hour and a half at 400 Hz).
#include "verify/module_check.h"

#include "model/sample.h"

#include <string>
#include <vector>

namespace imudesk::verify {

// A sample's time (s): the module's own clock where the frame carries one, else its arrival.
double sampleTimeS(const model::Sample &s);
// The attitude a sample reports (body to its world frame): the quaternion, else the Euler
// angles (ENU 3-1-2); false when it carries neither.
bool reportedAttitude(const model::Sample &s, Eigen::Quaterniond &out);

class MotionInput {
public:
    static constexpr size_t kMaxSamples = 2'000'000;

    void add(const model::Sample &s);
    const std::vector<MotionSample> &samples() const { return m_samples; }
    std::vector<MotionSample> takeSamples() { return std::move(m_samples); }
    const std::string &source() const { return m_source; } // the frame type read ("HI91")
    size_t passedOver() const { return m_passedOver; }        // of that type without acc or gyro, or past the bound
    size_t clockJumps() const { return m_clockJumps; }        // times that ran backwards, carried across
    bool full() const { return m_samples.size() >= kMaxSamples; }

private:
    std::vector<MotionSample> m_samples;
    std::string m_source;
    size_t m_passedOver = 0;
    size_t m_clockJumps = 0;
    double m_offsetS = 0;
    double m_lastDtS = 0;
};

} // namespace imudesk::verify
