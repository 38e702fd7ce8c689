#pragma once
// The heading check after a magnetometer calibration (v1.7.1 9.30: "turn the module level one
// full turn: the heading must change continuously"): the module is turned 360 deg flat and the
// heading followed sample by sample. It passes once the turns add up to 360 deg with no step
// between two samples above kMaxJumpDeg (a jump is a calibration that does not hold; chapter
// 9.31). The wizard's heading page and `imudesk-cli calibrate PORT mag|heading-check` use it.
// A plain value class: the caller feeds headings in degrees (any range; steps across +-180 or
// 0/360 are unwrapped).
namespace imudesk::calib {

class HeadingTurnCheck {
public:
    static constexpr double kTurnDeg = 360.0;
    static constexpr double kMaxJumpDeg = 10.0;

    enum class Verdict { KeepTurning, Passed, Jumped };

    void reset();
    void add(double headingDeg);

    double turnedDeg() const { return m_turned; }   // the steps' absolute sum
    double maxJumpDeg() const { return m_maxJump; } // the largest step between two samples
    int samples() const { return m_samples; }
    Verdict verdict() const;
    bool passed() const { return verdict() == Verdict::Passed; }

private:
    bool m_have = false;
    double m_last = 0;
    double m_turned = 0;
    double m_maxJump = 0;
    int m_samples = 0;
};

} // namespace imudesk::calib
