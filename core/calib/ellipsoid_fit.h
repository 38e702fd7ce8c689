#pragma once
// Magnetometer ellipsoid fits (calibration-notes.md §1.1, §2.1, §8), all in Eigen and
// deterministic (no random numbers, no threads: the same input gives bit-identical output).
//
// Model: m = A h + b + n. The fit returns the hard iron b and a symmetric correction W
// with |W (m - b)| = 1 for every sample on the ellipsoid (W maps the ellipsoid onto the
// unit sphere). The field strength is 1 / cbrt(det W); the soft-iron matrix with
// det = 1 is W * fieldStrength.
//
//  * algebraicLi: Li & Griffiths (2004) ellipsoid-specific least squares (k = 4) on
//    mean-centred, RMS-scaled data; always an ellipsoid when it succeeds.
//  * refine: geometric Levenberg-Marquardt on r_i = |W (m_i - b)| - 1 over b and the six
//    entries of W, with Huber weights (IRLS, delta = 3 * 1.4826 * MAD of the residuals).
//  * hardIronOnly: b (and optionally the radius) with the soft iron held fixed (robust).
#include <Eigen/Core>

#include <optional>
#include <vector>

namespace imudesk::calib {

struct Ellipsoid {
    Eigen::Vector3d center = Eigen::Vector3d::Zero(); // hard iron (input units)
    Eigen::Matrix3d w = Eigen::Matrix3d::Identity();  // symmetric, positive definite
    // Field strength in input units: 1 / cbrt(det W).
    double radius() const;
    // W with det = 1 (the soft-iron correction).
    Eigen::Matrix3d softIron() const;
    // Corrected vector in input units: softIron() * (m - center) has length radius().
    Eigen::Vector3d correct(const Eigen::Vector3d &m) const;
};

struct RobustStats {
    int iterations = 0;
    double sigma = 0;      // robust residual scale (1.4826 * MAD); refine: relative to the data RMS radius,
    double delta = 0;      // hardIronOnly: input units. Huber threshold used last, same units
    int outliers = 0;      // samples with |r| > 5 sigma (and > delta)
    bool converged = false;
};

class EllipsoidFit {
public:
    static constexpr int kMinPoints = 10;
    static constexpr int kMaxLmIterations = 60;

    // Li & Griffiths ellipsoid-specific fit; nullopt when the data cannot give one.
    static std::optional<Ellipsoid> algebraicLi(const std::vector<Eigen::Vector3d> &points);
    // Huber-LM refinement seeded by `start`; keeps `start` when a step cannot improve it.
    static Ellipsoid refine(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &start,
                            RobustStats *stats = nullptr);
    // Linear (Kasa) sphere fit: centre and radius; nullopt for fewer than 4 distinct points.
    static std::optional<std::pair<Eigen::Vector3d, double>> sphere(const std::vector<Eigen::Vector3d> &points);
    // Hard iron with the soft iron `softIron` (det 1) held fixed. With fixedRadius > 0 the
    // field strength is held too (e.g. from the world magnetic model).
    static std::optional<Ellipsoid> hardIronOnly(const std::vector<Eigen::Vector3d> &points,
                                                 const Eigen::Matrix3d &softIron, double fixedRadius = 0,
                                                 RobustStats *stats = nullptr);
    // Residuals |W (m - b)| * radius - radius, in input units.
    static std::vector<double> residuals(const std::vector<Eigen::Vector3d> &points, const Ellipsoid &e);
    // Robust scale of values: 1.4826 * median(|v - median(v)|).
    static double robustSigma(std::vector<double> values);
};

} // namespace imudesk::calib
