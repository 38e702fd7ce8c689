#pragma once
// Live 3D view of magnetometer samples on a sphere for the calibration wizard: the 80
// geodesic cells (calib::SphereCoverage) drawn as a translucent globe, cells coloured as
// the field directions cover them, the samples as dots, and text with |B|, the coverage
// and the hint of which rotation is still missing.
//
// Directions are taken around a centre: the hard iron of setCalibration() when given
// (then the dots are the corrected samples, "after"), else the mean of the samples so far
// ("before"). Painted with QPainter (offscreen-safe), painter's algorithm on the cell
// centres' depth. Left-drag turns the view, double-click resets it. While samples come in
// (addSample) at most kMaxSamples are kept (every second one is dropped when full, so the
// spread stays); setSamples() keeps every sample of a finished run, so that its cells are
// the run's coverage. The readout counts every sample given, not the ones kept.
//
// A finished run (showRun) is read out from its result, not from the view's own counts: the
// samples, coverage and predicted heading error the result page, the report and the saved
// run give, and no instruction (nothing is left to turn). Q_PROPERTY readout: the text drawn.
#include "calib/mag_cal_result.h"
#include "calib/sphere_coverage.h"

#include <Eigen/Core>

#include <QWidget>

#include <vector>

namespace imudesk::ui {

class MagSphereView : public QWidget {
    Q_OBJECT
    Q_PROPERTY(QString readout READ readoutText)
public:
    static constexpr size_t kMaxSamples = 4000;

    explicit MagSphereView(QWidget *parent = nullptr);

    void clear();
    void addSample(const Eigen::Vector3d &magUt);
    void setSamples(const std::vector<Eigen::Vector3d> &magUt);
    // Shows the samples corrected by c = S (m - b); clearCalibration() goes back to raw.
    void setCalibration(const Eigen::Vector3d &hardIron, const Eigen::Matrix3d &softIron);
    void clearCalibration();
    // Reads out the figures of this finished run instead of the live ones; clear() ends it.
    void showRun(const calib::MagCalResult &result);
    bool showsRun() const { return m_showsRun; }
    // The text under the sphere: live |B|, coverage, samples and the missing rotation, or
    // the finished run's figures.
    QString readoutText() const;

    const calib::SphereCoverage &coverage() const { return m_coverage; }
    double coveragePercent() const { return m_coverage.percent(); }
    QString hint() const { return m_coverage.missingRotationHint(); }
    double lastFieldUt() const { return m_lastField; }
    // The samples kept (at most kMaxSamples while they come in: thinned evenly), and every
    // sample given since clear() (what the readout counts: the samples taken, not the kept).
    size_t sampleCount() const { return m_samples.size(); }
    size_t totalSamples() const { return m_total; }
    const std::vector<Eigen::Vector3d> &samples() const { return m_samples; }

    QSize sizeHint() const override { return {360, 360}; }
    QSize minimumSizeHint() const override { return {160, 160}; }

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;

private:
    Eigen::Vector3d corrected(const Eigen::Vector3d &m) const;
    void rebuild();

    std::vector<Eigen::Vector3d> m_samples;
    size_t m_total = 0;
    Eigen::Vector3d m_sum = Eigen::Vector3d::Zero();
    bool m_calibrated = false;
    Eigen::Vector3d m_hardIron = Eigen::Vector3d::Zero();
    Eigen::Matrix3d m_softIron = Eigen::Matrix3d::Identity();
    calib::SphereCoverage m_coverage;
    calib::MagCalResult m_run;
    bool m_showsRun = false;
    double m_lastField = 0;
    double m_azimuthDeg = 30, m_elevationDeg = 20;
    QPoint m_dragFrom;
};

} // namespace imudesk::ui
