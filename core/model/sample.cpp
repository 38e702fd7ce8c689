#include "sample.h"

#include <cmath>

namespace imudesk::model {

void mergeFields(Sample &dst, const Sample &src)
{
    const uint32_t f = src.fields;
    if (f & FieldAcc) dst.acc = src.acc;
    if (f & FieldGyr) dst.gyr = src.gyr;
    if (f & FieldMag) dst.mag = src.mag;
    if (f & FieldEuler) {
        dst.roll = src.roll;
        dst.pitch = src.pitch;
        dst.yaw = src.yaw;
    }
    if (f & FieldQuat) dst.quat = src.quat;
    if (f & FieldPressure) dst.pressurePa = src.pressurePa;
    if (f & FieldTemperature) dst.temperatureC = src.temperatureC;
    if (f & FieldDeviceTime) dst.deviceTimeMs = src.deviceTimeMs;
    if (f & FieldMainStatus) dst.mainStatus = src.mainStatus;
    if (f & FieldPosition) {
        // NaN altitude: the sentence has none (NMEA RMC); keep the last one known.
        if (!std::isnan(src.altitudeM) || !(dst.fields & FieldPosition))
            dst.altitudeM = src.altitudeM;
        dst.latitudeDeg = src.latitudeDeg;
        dst.longitudeDeg = src.longitudeDeg;
    }
    if (f & FieldVelocity) dst.velEnu = src.velEnu;
    if (f & FieldHeave) dst.heaveSurgeSway = src.heaveSurgeSway;
    if (f & FieldInclination) {
        dst.inclinationX = src.inclinationX;
        dst.inclinationY = src.inclinationY;
    }
    if (f & FieldInsStatus) dst.insStatus = src.insStatus;
    if (f & FieldGnss) { // an RMC reports time but no fix quality: keep the last GGA's
        if (src.gnssQuality >= 0) {
            dst.gnssQuality = src.gnssQuality;
            dst.gnssSatellites = src.gnssSatellites;
        }
        if (src.utcTimeOfDayS >= 0)
            dst.utcTimeOfDayS = src.utcTimeOfDayS;
    }
    if (f & FieldMagRelative) dst.magRelative = src.magRelative;
    if (f & FieldMagRoll) dst.magRollDeg = src.magRollDeg;
    if (f & FieldHeading) {
        dst.headingDeg = src.headingDeg;
        dst.headingTrue = src.headingTrue;
    }
    if ((f & FieldHi83Extra) && src.hi83) {
        // Share the newer block when it carries every field the older one did (one module's
        // frames all have the same bitmap); otherwise merge field by field.
        if (!dst.hi83 || (dst.hi83->bits & ~src.hi83->bits) == 0) {
            dst.hi83 = src.hi83;
        } else {
            auto merged = std::make_shared<Hi83Extra>(*dst.hi83);
            const Hi83Extra &n = *src.hi83;
            auto take = [&](int bit, auto member) {
                if (n.has(bit)) merged.get()->*member = n.*member;
            };
            take(6, &Hi83Extra::utcDate);
            take(11, &Hi83Extra::hssFreqHz);
            take(13, &Hi83Extra::accEnu);
            if (n.has(15)) {
                merged->solqPos = n.solqPos;
                merged->nvPos = n.nvPos;
                merged->solqHeading = n.solqHeading;
                merged->nvHeading = n.nvHeading;
            }
            take(16, &Hi83Extra::odSpeedMs);
            take(17, &Hi83Extra::undulationM);
            take(18, &Hi83Extra::diffAgeS);
            take(19, &Hi83Extra::nodeId);
            take(25, &Hi83Extra::eventCounter);
            take(26, &Hi83Extra::kfAccBias);
            take(27, &Hi83Extra::kfGyrBias);
            take(28, &Hi83Extra::gnssStd);
            take(29, &Hi83Extra::dualHeading);
            take(30, &Hi83Extra::gnssLonLatMsl);
            take(31, &Hi83Extra::gnssVelEnu);
            merged->bits |= n.bits;
            dst.hi83 = std::move(merged);
        }
    }
    dst.fields |= f;
    dst.source = src.source;
    dst.hostTimeNs = src.hostTimeNs;
    if (src.commonTimeNs != 0)
        dst.commonTimeNs = src.commonTimeNs;
}

} // namespace imudesk::model
