#pragma once
// The gyro scale run's big picture: a ring that fills as the module turns, one lap per
// 360 deg, with the target's stop mark and the window around it (target +- tolerance), the
// angle turned and the target in the middle, the laps and the turn rate below, the rate
// coloured by the manual's 20..100 deg/s band. Painted with QPainter (tests render it
// offscreen); it only shows what it is given (GyroScaleWizard feeds it on its clock).
#include <QWidget>

namespace imudesk::ui {

class TurnGauge : public QWidget {
    Q_OBJECT
public:
    explicit TurnGauge(QWidget *parent = nullptr);

    void setTarget(double targetDeg, double toleranceDeg);
    // The angle turned so far (magnitude) and the current rate (deg/s, magnitude); the rate
    // band colours the rate text.
    void setProgress(double angleDeg, double rateDps);
    void setRateBand(double minDps, double maxDps);
    void clear();

    double target() const { return m_target; }
    double angle() const { return m_angle; }
    // Where the ring's fill ends in the current lap (0..360 deg, clockwise from the top) and
    // whether the angle is inside the stop window.
    double lapDeg() const;
    bool inStopWindow() const;
    // The centre's text ("412 deg of 720 deg"), for tests and screen readers.
    QString centreText() const;
    QString detailText() const;

    QSize sizeHint() const override { return {360, 360}; }
    QSize minimumSizeHint() const override { return {200, 200}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    double m_target = 720.0;
    double m_tolerance = 5.0;
    double m_angle = 0.0;
    double m_rate = 0.0;
    double m_minRate = 20.0;
    double m_maxRate = 100.0;
    bool m_started = false;
};

} // namespace imudesk::ui
