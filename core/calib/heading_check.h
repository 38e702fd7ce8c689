#pragma once
// The heading check after a magnetometer calibration (manual v1.7.1 chapter 9.31): turn the
// module one full turn, level; the heading must follow the turn without jumps. A plain value
// class fed with the module's samples (Euler angles; the gyro and the field when the output
// carries them), so the wizard and its tests judge the same way.
//
// Only a level turn in a steady field can show a calibration's fault; everything else is said
// as what to do or why the check cannot judge (issue 53: on a tumbling module the Euler yaw
// swings near 90 deg of pitch, and the old check said "calibrate again" right after a fit
// and the module's MCAL had both passed):
//   Tilted          the newest sample's roll or pitch is beyond kMaxTiltDeg: "keep the module
//                   level while you turn it". A tilted module's heading moves with the tilt too,
//                   so its steps are not judged and its turn does not count.
//   FieldDisturbed  the newest sample's |B| (corrected, see setFieldCorrection) is more than
//                   kMaxFieldChangePct off the median of the level turn: iron or a current
//                   nearby; steps there are not judged either.
//   TurnMore        level and steady, but less than kFullTurnDeg turned so far.
//   Jumps           between two level samples in a steady field the heading stepped by more
//                   than kMaxJumpDeg beyond what the gyro turned (when the output carries it):
//                   that is the calibration, or the module's use of it. Final until reset().
//   Passed          kFullTurnDeg turned level, in a steady field, without a jump. Final.
#include <Eigen/Core>

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace imudesk::model {
struct Sample;
}

namespace imudesk::calib {

class HeadingCheck {
    Q_DECLARE_TR_FUNCTIONS(HeadingCheck)

public:
    enum class Status { TurnMore, Tilted, FieldDisturbed, Jumps, Passed };

    static constexpr double kFullTurnDeg = 360.0;
    static constexpr double kMaxJumpDeg = 10.0;        // manual 9.31: no jump of more than 10 deg
    static constexpr double kMaxTiltDeg = 15.0;        // roll and pitch within this count as level
    static constexpr double kMaxFieldChangePct = 15.0; // |B| off the level turn's median
    static constexpr int kFieldReferenceSamples = 20;  // level samples before |B| is judged

    HeadingCheck() = default;

    void reset();
    // The field is judged as c = softIron * (m - hardIron) (ImuDesk's fit of raw samples);
    // identity when the module corrects its own output. Without a correction (the default
    // until set) the field is not judged.
    void setFieldCorrection(const Eigen::Vector3d &hardIron, const Eigen::Matrix3d &softIron);
    void clearFieldCorrection();

    // Samples without Euler angles are skipped.
    void add(const model::Sample &s);

    Status status() const;
    bool passed() const { return status() == Status::Passed; }
    // Degrees turned level in a steady field (what counts towards the full turn).
    double levelTurnDeg() const { return m_levelTurn; }
    // Degrees turned in all (level or not).
    double totalTurnDeg() const { return m_totalTurn; }
    // The largest step judged (level, steady), beyond the gyro's turn; the largest jump counted.
    double largestJudgedStepDeg() const { return m_largestJudgedStep; }
    // The tilt of the newest sample and the largest seen (deg).
    double tiltDeg() const { return m_tilt; }
    double largestTiltDeg() const { return m_largestTilt; }
    // The newest sample's |B| off the reference (%); NaN while the field is not judged.
    double fieldChangePct() const { return m_fieldChangePct; }
    // Steps above kMaxJumpDeg that were not judged, because the module was tilted or the field
    // disturbed at the time.
    int unjudgedJumps() const { return m_unjudgedJumps; }
    // What to do next, or why the check cannot judge (translated).
    QString advice() const;

private:
    std::optional<Eigen::Vector3d> m_hardIron;
    Eigen::Matrix3d m_softIron = Eigen::Matrix3d::Identity();

    bool m_haveLast = false;
    double m_lastYaw = 0;
    double m_lastTimeS = 0;
    bool m_lastJudgeable = false;
    double m_levelTurn = 0, m_totalTurn = 0;
    double m_largestJudgedStep = 0;
    double m_tilt = 0, m_largestTilt = 0;
    bool m_tilted = false, m_disturbed = false;
    double m_fieldChangePct = std::numeric_limits<double>::quiet_NaN();
    bool m_jumped = false;
    int m_unjudgedJumps = 0;
    std::vector<double> m_levelFields;
    double m_referenceField = 0;
};

} // namespace imudesk::calib
