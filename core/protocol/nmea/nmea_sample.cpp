#include "nmea_sample.h"
#include "model/attitude.h"

#include <cmath>

namespace imudesk::protocol::nmea {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

void setTime(model::Sample &s, const std::optional<UtcTime> &t)
{
    if (!t)
        return;
    s.utcTimeOfDayS = t->hour * 3600.0 + t->minute * 60.0 + t->second;
    s.fields |= model::FieldGnss;
}

void setPosition(model::Sample &s, std::optional<double> lat, std::optional<double> lon, std::optional<double> alt)
{
    if (!lat || !lon)
        return;
    s.latitudeDeg = *lat;
    s.longitudeDeg = *lon;
    s.altitudeM = alt.value_or(0);
    s.fields |= model::FieldPosition;
}

} // namespace

std::optional<model::Sample> toSample(const Sentence &sentence)
{
    model::Sample s;
    s.source = sentence.type;
    if (const auto &g = sentence.gga) {
        s.gnssQuality = g->quality;
        s.gnssSatellites = g->satellites;
        s.fields |= model::FieldGnss;
        setTime(s, g->time);
        if (g->quality > 0) // no fix: the position fields are empty or stale
            setPosition(s, g->latitudeDeg, g->longitudeDeg, g->altitudeM);
    } else if (const auto &r = sentence.rmc) {
        setTime(s, r->time);
        if (r->valid) {
            // RMC carries no altitude: keep the one a GGA or SXT gave (mergeFields copies all three).
            if (r->latitudeDeg && r->longitudeDeg) {
                s.latitudeDeg = *r->latitudeDeg;
                s.longitudeDeg = *r->longitudeDeg;
                s.altitudeM = std::nan("");
                s.fields |= model::FieldPosition;
            }
            if (r->speedKnots && r->courseDeg) {
                const double v = r->speedMs();
                s.velEnu = {v * std::sin(*r->courseDeg * kDegToRad), v * std::cos(*r->courseDeg * kDegToRad), 0.0};
                s.fields |= model::FieldVelocity;
            }
        }
    } else if (const auto &x = sentence.sxt) {
        s.gnssQuality = x->quality;
        s.gnssSatellites = x->satellites;
        s.fields |= model::FieldGnss;
        setTime(s, x->time);
        setPosition(s, x->latitudeDeg, x->longitudeDeg, x->altitudeM);
        if (x->rollDeg && x->pitchDeg && x->headingDeg) {
            s.roll = *x->rollDeg;
            s.pitch = *x->pitchDeg;
            model::setCompassHeading(s, *x->headingDeg, true); // yaw: ENU, counter-clockwise
            s.fields |= model::FieldEuler;
        }
        if (x->velEnuMs[0] && x->velEnuMs[1] && x->velEnuMs[2]) {
            s.velEnu = {*x->velEnuMs[0], *x->velEnuMs[1], *x->velEnuMs[2]};
            s.fields |= model::FieldVelocity;
        }
    } else if (const auto &h = sentence.heading) {
        s.headingDeg = h->headingDeg;
        s.headingTrue = h->trueNorth;
        s.fields |= model::FieldHeading;
    }
    if (s.fields == 0)
        return std::nullopt;
    return s;
}

std::optional<model::Sample> sampleOf(std::string_view line)
{
    const ParseResult parsed = parseSentence(line);
    return parsed.sentence ? toSample(*parsed.sentence) : std::nullopt;
}

} // namespace imudesk::protocol::nmea
