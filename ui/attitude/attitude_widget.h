#pragma once
// 3D attitude view: the module as a shaded box with its X/Y/Z axes, over a ground grid
// with a north arrow, and roll/pitch/yaw/heading read-outs in the top-left corner.
//
// Painted with QPainter (QOpenGLWidget does not run offscreen) from a small perspective
// projection done with Eigen; painter's algorithm (ground, far axes, visible faces back
// to front, near axes, labels). The scene is always built in the ENU navigation frame
// (x East, y North, z Up) with the module's printed body axes x right, y forward, z up
// (X red, Y green, Z blue). The module is a 3 : 2 : 0.6 box (X : Y : Z); its top face is
// dark blue with an amber arrow pointing forward (+Y) and a dark connector along the back
// (-Y) edge, so an upside-down module shows the plain grey bottom instead. The ground
// grid lies below the module (z = -1.9) with a north arrow labelled "N", the module's
// vertical shadow, and a navigation-frame triad at its south-west corner.
//
// Display frame: only the read-outs and the triad change. ENU shows the ENU 3-1-2 Euler
// angles and labels the triad E (x), N (y), U (z); NED shows the NED 3-2-1 angles of the
// body(FRD) -> NED quaternion and labels it N (x), E (y), D (z) (see model/attitude.h:
// roll and pitch agree, yaw_ned = -yaw_enu). The drawn body arrows stay the module's
// printed X/Y/Z. Heading (0..360, clockwise from north) is the same in both.
//
// World frame: a module set to CONFIG IMU COORD 4 sends body -> NWU (North-West-Up). Given
// setWorldFrame(Nwu), the widget turns its quaternion into ENU for the scene (so north is
// where the grid's arrow points), and its own frame replaces ENU in the read-outs and the
// menu: "NWU 3-1-2", the NWU Euler angles (yaw 0 with the module's Y axis west) and a triad
// N (x), W (y), U (z). NED stays available and means the same physical attitude.
//
// Camera: looks at (0, 0, -1.1), just below the module's centre, from the south-east and
// above: bearing kDefaultAzimuthDeg (compass bearing of the camera seen from the module,
// clockwise from north) and kDefaultElevationDeg above the horizon, kCameraDistance scene
// units away, world up drawn up, light fixed to the camera (upper left). Left-drag orbits
// the camera (right/left changes the bearing, down/up the elevation, clamped to
// +-89 deg), double-click resets it; the context menu picks the display frame and resets
// the view.
//
// The workspace calls setQuaternion() on its refresh clock; the widget repaints only when
// the value changed. Before the first quaternion it shows a grey "no data" state.
// Per paint: fixed-size arrays only; texts are laid out (QStaticText) when they change.
//
// Folder ui/attitude/: the orientation views, painted with QPainter: this AttitudeWidget, the
// HEC495 HeadingDial and the CompassPoseView of the HEC495 calibration methods. They mirror
// core/model's attitude: AttitudeWidget uses model/attitude.h (quaternion and Euler angles, ENU
// or NED) on the latest Sample, HeadingDial is given a Sample's heading, pitch and roll, and
// CompassPoseView draws the targets of core/calib's CompassPoseTracker. No item models: each
// view is given the latest values on its owner's clock (the device workspace or the HEC495
// calibration wizard).
#include "model/device_identity.h"
#include "model/sample.h"

#include <QStaticText>
#include <QPixmap>
#include <QWidget>

#include <vector>

#include <array>

namespace imudesk::ui {

class AttitudeWidget : public QWidget {
    Q_OBJECT
public:
    enum class DisplayFrame {
        Enu, // ENU 3-1-2 read-outs, world axes E/N/U (the devices' default)
        Ned, // NED 3-2-1 read-outs, world axes N/E/D
    };
    Q_ENUM(DisplayFrame)

    static constexpr double kDefaultAzimuthDeg = 135.0;  // south-east
    static constexpr double kDefaultElevationDeg = 30.0; // above the horizon
    static constexpr double kCameraDistance = 13.0;      // scene units (the box is 3 x 2 x 0.6)
    static constexpr double kMaxElevationDeg = 89.0;

    explicit AttitudeWidget(QWidget *parent = nullptr);
    ~AttitudeWidget() override;

    // Body -> world quaternion (w, x, y, z), as the devices send it (ENU, or NWU after
    // setWorldFrame(Nwu)). Stored normalised; a repaint is scheduled only when the value
    // differs from the last one. Non-finite or zero quaternions are ignored.
    void setQuaternion(const model::Quat &q);
    // The last accepted quaternion as body -> ENU, normalised (identity before the first one).
    model::Quat quaternion() const { return m_quat; }
    // The module's world frame (identity.worldFrame); the last quaternion is taken again in it.
    // assumed: the module did not name it (identity.worldFrameAssumed: LOG COMCONFIG without
    // COORD): the read-out's title says so and the view shows frameWarning().
    void setWorldFrame(model::WorldFrame frame, bool assumed = false);
    model::WorldFrame worldFrame() const { return m_world; }
    bool worldFrameAssumed() const { return m_worldAssumed; }
    // Why the frame is in doubt ("" when the module named it), drawn under the read-out.
    QString frameWarning() const;
    bool hasData() const { return m_hasData; }
    // Back to the "no data" state.
    void clear();

    // A second attitude drawn as an outline beside the module (issue 55: ImuDesk's reference
    // filter, verify/live_reference.h), in the same world frame as setQuaternion's, with a
    // caption under the scene ("Reference 1.2° apart"). The context menu offers it
    // (ghostRequested); setGhostShown(false) takes it away.
    void setGhost(const model::Quat &q, const QString &caption);
    // The angle between the module and the reference at tS (seconds, any clock that only goes
    // forward): the last kGhostTraceS of it drawn as a small chart under the caption.
    static constexpr double kGhostTraceS = 30.0;
    static constexpr size_t kGhostTraceMax = 2000;
    void addGhostDifference(double tS, double apartDeg);
    const std::vector<QPointF> &ghostTrace() const { return m_ghostTrace; }
    void setGhostShown(bool shown);
    bool ghostShown() const { return m_ghostShown; }
    model::Quat ghost() const { return m_ghost; }
    QString ghostCaption() const { return m_ghostCaption; }

    void setDisplayFrame(DisplayFrame frame);
    DisplayFrame displayFrame() const { return m_frame; }

    // Camera bearing (deg clockwise from north, wrapped to 0..360) and elevation (deg,
    // clamped to +-kMaxElevationDeg).
    void setCameraAngles(double azimuthDeg, double elevationDeg);
    double cameraAzimuth() const { return m_azimuth; }
    double cameraElevation() const { return m_elevation; }
    void resetCamera();

    // The read-out as shown, one line each: frame title, roll, pitch, yaw, heading
    // ("Roll 13.1°"); "No attitude yet" in the no-data state.
    QString readoutText() const;

    // Where a point given in the ENU navigation frame (scene units, module centre at the
    // origin, the module 3 x 2 x 0.6) lands in widget coordinates with the current camera.
    QPointF screenPosition(const model::Vec3 &enu) const;
    // The read-out panel and the area the 3D scene is fitted into: beside the panel when
    // the widget is wide, below it when it is tall; the two never overlap.
    QRectF readoutRect() const { return m_panel; }
    QRectF sceneRect() const;
    // Where the model, its grid and axes are fitted: the scene less room for the axis names.
    QRectF modelArea() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

Q_SIGNALS:
    void displayFrameChanged(imudesk::ui::AttitudeWidget::DisplayFrame frame);
    // The user asked for the reference attitude to be shown or hidden (context menu).
    void ghostRequested(bool shown);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    // A quaternion as the module sends it, turned into the ENU scene.
    model::Quat inScene(const model::Quat &q) const;
    // The module's own frame and angles: "ENU 3-1-2", or "NWU 3-1-2" for a module set to NWU.
    QString ownFrameTitle() const;
    struct View; // camera and projection, defined in the .cpp (Eigen stays out of this header)

    void retranslate();
    void updateReadouts();
    // The ground: its lines (grid, north arrow, navigation triad; they depend on the camera
    // only), the module's shadow, or (labels) the world-axis labels.
    void paintGround(QPainter &p, const View &v, bool labels) const;
    void paintGroundLines(QPainter &p, const View &v) const;
    void paintShadow(QPainter &p, const View &v) const;
    // The background with the ground's lines, from a pixmap made again only when the camera,
    // the size or the palette changes.
    void paintCachedGround(QPainter &p, const View &v) const;
    void paintBody(QPainter &p, const View &v) const;
    void paintAxes(QPainter &p, const View &v, bool nearSide, bool labels) const;
    void paintReadouts(QPainter &p) const;
    void paintGhost(QPainter &p) const;

    bool m_ghostShown = false;
    model::Quat m_ghost{};  // normalised, in the scene's frame
    QString m_ghostCaption;
    std::vector<QPointF> m_ghostTrace; // (t, angle apart), oldest first
    model::Quat m_input{};  // last value passed in, as given (change detection)
    model::Quat m_quat{};   // normalised
    bool m_hasData = false;
    DisplayFrame m_frame = DisplayFrame::Enu;
    model::WorldFrame m_world = model::WorldFrame::Enu;
    bool m_worldAssumed = false;
    double m_azimuth = kDefaultAzimuthDeg;
    double m_elevation = kDefaultElevationDeg;

    bool m_dragging = false;
    QPointF m_lastMouse;

    struct GroundKey {
        QSize size;
        qreal dpr = 0;
        double azimuth = 0, elevation = 0;
        DisplayFrame frame = DisplayFrame::Enu;
        model::WorldFrame world = model::WorldFrame::Enu;
        bool hasData = false;
        QRgb base = 0, ink = 0;
        bool operator==(const GroundKey &) const = default;
    };
    mutable QPixmap m_ground;
    mutable GroundKey m_groundKey;

    // Text prepared on change, not per paint.
    std::array<QStaticText, 3> m_axisLabels;  // X, Y, Z
    std::array<QStaticText, 3> m_worldLabels; // the navigation axes, per display frame
    QStaticText m_northLabel;
    QString m_noDataText;
    QString m_frameTitle;
    std::array<QString, 4> m_readoutNames;  // Roll, Pitch, Yaw, Heading
    std::array<QString, 4> m_readoutValues; // "13.1°"
    QFont m_boldFont;
    QStaticText m_noDataStatic;
    QStaticText m_titleStatic;
    std::array<QStaticText, 4> m_nameStatic;
    std::array<QStaticText, 4> m_valueStatic;
    QRectF m_panel;
    double m_lineSpacing = 0;
};

} // namespace imudesk::ui
