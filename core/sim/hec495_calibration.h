#pragma once
// The magnetic calibration of a simulated HEC495 (manual "校准方法"): which points each of
// the five methods collects, and the fit that saving computes.
//
// Point collection (pose = true compass heading, pitch and roll of the simulated motion):
//   Auto12 (0x63)       the 12 poses of table 1: heading within +-kHeadingToleranceDeg of
//                       the table's, pitch -5..+5 / >+45 / <-45, roll 30..40 or -40..-30
//   SmallTilt12 (0x64)  the 12 poses of table 4: as Auto12 with roll -5..+5
//   Planar (0x60)       pitch and roll within +-2 deg (the method table's limit); one point
//                       per 30 deg heading sector, 12 at most
//   AllOrientation (0x08) one point per new direction of the field in the body frame
//                       (8 latitude bands x 12 sectors), 96 at most (as the manual says)
//   Manual (0x65)       a point on each "collect point" command (0x67), 96 at most
// Minimum points to save: Manual 12 (the manual's "最少 12 点"), Auto12/SmallTilt12 6,
// AllOrientation 12, Planar 4; fewer, or points that do not span the field, fail.
//
// Fit: the hard-iron offset c and field radius r of the collected raw magnetometer vectors,
// by linear least squares (|m - c|^2 = r^2): a sphere, or for Planar a circle in the body
// x-y plane (c_z = 0). Fit error = 100 * RMS(|m - c| - r) / r, in percent of the field:
// what remains is soft iron and noise, so the error reflects the simulated distortion.
// The HEC495 asks to calibrate again above 10.
#include "protocol/witlink/commands.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace imudesk::sim {

class Hec495Calibration {
public:
    using Method = protocol::witlink::CalibrationMethod;
    static constexpr double kHeadingToleranceDeg = 15.0;
    static constexpr double kPlanarTiltDeg = 2.0;
    static constexpr int kMaxPoints = 96;

    struct Pose {
        double heading = 0, pitch = 0, roll = 0; // deg; heading clockwise from north, 0..360
    };
    struct Result {
        Eigen::Vector3d hardIron = Eigen::Vector3d::Zero();
        double radius = 0;
        float fitError = 0;
        int points = 0;
    };

    void start(Method m);
    void stop();
    bool active() const { return m_method.has_value(); }
    std::optional<Method> method() const { return m_method; }
    int points() const { return int(m_points.size()); }

    // Automatic methods: takes a point when the pose matches a slot not yet taken.
    bool offer(const Pose &pose, const Eigen::Vector3d &rawMag);
    // "Collect point" (0x67): false when no calibration runs or the run is full.
    bool collect(const Eigen::Vector3d &rawMag);
    // Saving: the fit of the points so far (nullopt: too few or degenerate). Ends the run.
    std::optional<Result> finish();

    static int minimumPoints(Method m);
    // Index of the table-1/table-4 slot the pose matches, or -1.
    static int tableSlot(Method m, const Pose &pose);

private:
    int slotFor(const Pose &pose, const Eigen::Vector3d &rawMag) const;

    std::optional<Method> m_method;
    std::vector<Eigen::Vector3d> m_points;
    std::vector<bool> m_taken;
};

} // namespace imudesk::sim
