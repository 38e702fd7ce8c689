#pragma once
// The HEC495 compass calibration methods (HEC495 manual, "校准方法") and, for the two
// methods with a pose table, which target poses have been collected.
//
//   Auto12 (77 04 00 63): 12 poses: headings 0/90/180/270 at pitch -5..+5, 30/120/210/300
//       at pitch > +45, 60/150/240/330 at pitch < -45; roll alternately 30..40 and -30..-40.
//   Manual (65, points saved with 67): at least 12 user-chosen poses; no table.
//   AutoAllOrientation (08): up to 96 points, every orientation; no table.
//   Auto12SmallTilt (64): the Auto12 headings and pitches with roll -5..+5 (roll < 5 deg).
//   Planar (60): up to 12 points while turning one circle level (pitch, roll < 2 deg);
//       shown as 12 headings 30 deg apart.
// A target is collected when the device reports a new valid point (0x66 reply) while the
// compass is at that pose (heading within headingToleranceDeg, pitch and roll within the
// ranges widened by rangeMarginDeg: the manual says no exact alignment is needed). After
// save, FitErr > 10 means: calibrate again.
#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <vector>

namespace imudesk::calib {

enum class CompassCalMethod { Auto12, Manual, AutoAllOrientation, Auto12SmallTilt, Planar };

struct PoseTarget {
    int number = 0;              // 1-based, as in the manual's table
    double headingDeg = 0;
    double pitchMinDeg = 0, pitchMaxDeg = 0;
    double rollMinDeg = 0, rollMaxDeg = 0;
};

class CompassPoseTracker {
    Q_DECLARE_TR_FUNCTIONS(CompassPoseTracker)

public:
    static constexpr double kMaxGoodFitErr = 10.0;

    static std::vector<PoseTarget> targets(CompassCalMethod m);
    static int maxPoints(CompassCalMethod m);   // 12, 0 = no limit (Manual), 96, 12, 12
    static int minPoints(CompassCalMethod m);   // points needed before saving makes sense
    static uint8_t startCommandCode(CompassCalMethod m); // command byte after "77 04 00"
    static QString methodName(CompassCalMethod m);
    static QString instructions(CompassCalMethod m);
    static bool fitErrAcceptable(double fitErr) { return fitErr <= kMaxGoodFitErr; }

    explicit CompassPoseTracker(CompassCalMethod method, double headingToleranceDeg = 15.0, double rangeMarginDeg = 5.0);

    CompassCalMethod method() const { return m_method; }
    const std::vector<PoseTarget> &poseTargets() const { return m_targets; }
    void clear();
    // The compass's current attitude; returns the index of the target it is at, or -1.
    int updatePose(double headingDeg, double pitchDeg, double rollDeg);
    // The valid-point count from the device's 0x66 reply; returns the index of a target
    // collected by this point, or -1.
    int setValidPoints(int count);
    int validPoints() const { return m_validPoints; }
    int currentTarget() const { return m_current; }
    bool collected(int index) const;
    int collectedCount() const;
    bool matches(const PoseTarget &t, double headingDeg, double pitchDeg, double rollDeg) const;
    double progressPct() const;
    bool readyToSave() const { return m_validPoints >= minPoints(m_method); }
    // What to do next (translated), e.g. "Turn to heading 90, pitch -5..+5, roll -30..-40".
    QString nextHint() const;

private:
    CompassCalMethod m_method;
    double m_headingTol;
    double m_margin;
    std::vector<PoseTarget> m_targets;
    std::vector<bool> m_collected;
    int m_validPoints = 0;
    int m_current = -1;
};

} // namespace imudesk::calib
