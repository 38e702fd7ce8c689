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
    dst.fields |= f;
    dst.source = src.source;
    dst.hostTimeNs = src.hostTimeNs;
}

} // namespace imudesk::model
