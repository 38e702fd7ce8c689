#pragma once
// The units the user wants to read acceleration and angular rate in. Samples always carry
// the devices' own units (G and deg/s, see sample.h); views multiply by these factors when
// they show a value, so a change of units never touches recorded data.
#include "model/sample.h"

#include <numbers>

namespace imudesk::model {

enum class AccelUnit { G, MetresPerSecondSquared };
enum class RateUnit { DegreesPerSecond, RadiansPerSecond };

struct DisplayUnits {
    AccelUnit accel = AccelUnit::G;
    RateUnit rate = RateUnit::DegreesPerSecond;

    // Factor from G to the shown acceleration unit (the vendor's 1 G = kGravity m/s²).
    double accelFactor() const { return accel == AccelUnit::G ? 1.0 : kGravity; }
    // Factor from deg/s to the shown rate unit.
    double rateFactor() const { return rate == RateUnit::DegreesPerSecond ? 1.0 : std::numbers::pi / 180.0; }
    friend bool operator==(const DisplayUnits &, const DisplayUnits &) = default;
};

} // namespace imudesk::model
