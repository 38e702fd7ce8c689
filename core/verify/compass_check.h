#pragma once
// Is the compass right? (issue 55, the HEC495) Its heading against known bearings: the operator
// turns it on a level compass rose to the marked bearings (4 or 8) and holds it still at each;
// its pitch and roll there against the rose's level. Each stop (the heading steady for minHoldS)
// is matched to the nearest marked bearing; the heading error at each bearing, the worst of them
// and their mean (a constant offset: declination, mounting) are judged with the same verdict as
// the module check (module_check.h): pass when the figure and its 95 % bound are within the pass
// limit, fail when the figure less its bound is beyond the fail limit, warn between, "cannot
// judge" with what to do when a bearing was never held.
#include "verify/module_check.h"

#include <vector>

namespace imudesk::verify {

struct CompassSample {
    double tS = 0;
    double headingDeg = 0; // clockwise from north, 0..360
    double pitchDeg = 0, rollDeg = 0;
};

struct CompassCheckOptions {
    std::vector<double> bearingsDeg{0, 90, 180, 270};
    double minHoldS = 2.0;           // a stop: the heading steady this long
    double maxHeadingSpreadDeg = 0.5; // steady: its standard deviation over the stop at most this
    double matchToleranceDeg = 20;   // a stop belongs to the marked bearing within this
    Limit headingDeg{1.0, 2.5};
    Limit tiltDeg{0.3, 1.0};
};

struct CompassStop {
    double fromS = 0, toS = 0;
    double headingDeg = 0, pitchDeg = 0, rollDeg = 0;
    double headingSigmaDeg = 0;      // of the stop's mean
    int bearing = -1;                // index into the bearings; -1: none near
    double errorDeg = 0;             // heading minus the bearing, -180..180
};

struct CompassReport {
    std::vector<CompassStop> stops;
    int bearingsHeld = 0;
    Figure worstHeadingErrDeg;       // the bearing whose error is largest (signed)
    double worstBearingDeg = 0;
    Figure meanHeadingErrDeg;        // the mean over the bearings: a constant offset
    Figure pitchErrDeg, rollErrDeg;  // against a level rose
    Verdict verdict = Verdict::CannotJudge;
    QStringList reasons;
};

CompassReport checkCompass(const std::vector<CompassSample> &samples, const CompassCheckOptions &options = {});

} // namespace imudesk::verify
