#pragma once
// 2-D (planar) magnetometer calibration: the direct ellipse-specific fit of Fitzgibbon,
// in the numerically stable form of Halir & Flusser (1998), on mean-centred, RMS-scaled
// (mx, my) (calibration-notes.md §2.3). For yaw-only motion the 3-D problem cannot be
// observed; this gives the horizontal offset (it absorbs the z cross terms) and a 2x2
// symmetric correction. Valid for level operation. Deterministic.
#include <Eigen/Core>

#include <optional>
#include <vector>

namespace imudesk::calib {

struct Ellipse {
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    Eigen::Matrix2d w = Eigen::Matrix2d::Identity(); // |W (m - c)| = 1 on the ellipse
    double radius() const;                            // horizontal field: 1 / sqrt(det W)
    Eigen::Matrix2d softIron() const;                 // W with det = 1
    Eigen::Vector2d correct(const Eigen::Vector2d &m) const;
};

class EllipseFit {
public:
    static constexpr int kMinPoints = 6;
    static std::optional<Ellipse> fit(const std::vector<Eigen::Vector2d> &points);
};

} // namespace imudesk::calib
