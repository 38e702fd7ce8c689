#pragma once
// A compass dial for a heading sensor (the Witlink HEC495): a fixed card with N/E/S/W,
// ticks every 10 deg and labels every 30 deg, a red needle pointing at the heading
// (clockwise from north, 0..360), and pitch and roll read-outs under the heading value.
// Painted with QPainter (works offscreen); repaints only when a shown value changes.
// Before the first setAttitude() (or after clear()) it shows a grey "no data" state.
//
// Self-contained: bind it to a session by calling setAttitude() from the workspace's
// refresh clock with the latest sample (Sample::yaw is the HEC495's heading).
#include <QWidget>

namespace imudesk::ui {

class HeadingDial : public QWidget {
    Q_OBJECT
public:
    static constexpr QRgb kNeedleColor = 0xffd32f2f;

    explicit HeadingDial(QWidget *parent = nullptr);

    // heading: deg, any value (wrapped to 0..360); pitch, roll: deg. Non-finite: ignored.
    void setAttitude(double headingDeg, double pitchDeg, double rollDeg);
    void clear();
    bool hasData() const { return m_hasData; }
    double heading() const { return m_heading; }
    double pitch() const { return m_pitch; }
    double roll() const { return m_roll; }
    // The texts under the dial ("313.7°", "pitch -26.80°  roll 33.65°"), or "no data".
    QString headingText() const;
    QString tiltText() const;

    QSize sizeHint() const override { return {260, 300}; }
    QSize minimumSizeHint() const override { return {120, 140}; }

protected:
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    bool m_hasData = false;
    double m_heading = 0, m_pitch = 0, m_roll = 0;
};

} // namespace imudesk::ui
