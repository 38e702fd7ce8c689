#pragma once
// The target poses of an HEC495 calibration method on a heading/pitch/roll display
// (QPainter): a compass rose with one target per pose of the method's table at its heading,
// on the ring of its pitch band (pitch up inside, level in the middle, pitch down outside)
// and with its roll range written next to it; collected targets are lit, the target the
// compass is at is outlined. The live pose is a needle at the heading with a dot at its
// pitch, and a roll bar below. Methods without a table show the point count as a ring.
#include "calib/compass_pose_tracker.h"

#include <QWidget>

#include <optional>

namespace imudesk::ui {

class CompassPoseView : public QWidget {
    Q_OBJECT
public:
    struct Pose {
        double heading = 0, pitch = 0, roll = 0; // deg, heading 0..360
    };

    explicit CompassPoseView(QWidget *parent = nullptr);

    // The tracker whose targets and collected flags are drawn (not owned; may be null).
    void setTracker(const calib::CompassPoseTracker *tracker);
    void setPose(std::optional<Pose> pose);
    std::optional<Pose> pose() const { return m_pose; }
    QSize sizeHint() const override { return {360, 400}; }
    QSize minimumSizeHint() const override { return {220, 250}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    const calib::CompassPoseTracker *m_tracker = nullptr;
    std::optional<Pose> m_pose;
};

} // namespace imudesk::ui
