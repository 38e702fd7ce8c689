#pragma once
// The rotations a magnetometer calibration asks for, drawn: the module three times, each with
// the turn about one of its axes (X red, Y green, Z blue, as in the 3D attitude view) and a
// caption under it. Painted with QPainter (tests render it offscreen); it shows no data.
#include <QStringList>
#include <QWidget>

namespace imudesk::ui {

class RotationGuide : public QWidget {
    Q_OBJECT
public:
    explicit RotationGuide(QWidget *parent = nullptr);

    // The three captions, in the order drawn (X, Y, Z), as shown.
    QStringList captions() const;

    QSize sizeHint() const override { return {720, 260}; }
    QSize minimumSizeHint() const override { return {360, 150}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;

protected:
    void paintEvent(QPaintEvent *event) override;
};

} // namespace imudesk::ui
