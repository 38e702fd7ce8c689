#include "attitude/attitude_widget.h"

#include "model/attitude.h"
#include "common/paint_helpers.h"

#include <QActionGroup>
#include <QContextMenuEvent>
#include <QEvent>
#include <QFontMetricsF>
#include <QLocale>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

namespace {

using Eigen::Vector3d;

// Scene, in scene units (ENU navigation frame, module centre at the origin).
constexpr double kHalfX = 1.5, kHalfY = 1.0, kHalfZ = 0.3; // module 3 : 2 : 0.6
constexpr std::array<double, 3> kAxisLength{kHalfX + 1.0, kHalfY + 1.3, kHalfZ + 1.2};
constexpr double kGroundZ = -1.9;  // below the module's bounding sphere (r = 1.83)
constexpr int kGridHalf = 3;       // grid lines at -3..3 in x and y
constexpr double kTriadLength = 1.2;
constexpr double kTargetZ = -1.1;  // the camera looks at (0, 0, kTargetZ): module and ground both fit
constexpr double kFitRadius = 4.3; // scene radius that fits into the widget
constexpr double kDragDegPerPixel = 0.5;
constexpr double kPanelMargin = 8, kPanelPadding = 6; // read-out panel, pixels

// Colours of the scene (fixed: the axes' colours carry meaning).
constexpr QRgb kAxisColours[3] = {qRgb(220, 50, 47), qRgb(40, 160, 60), qRgb(38, 110, 220)}; // X, Y, Z
constexpr QRgb kTopColour = qRgb(55, 85, 130);
constexpr QRgb kSideColour = qRgb(150, 160, 175);
constexpr QRgb kBottomColour = qRgb(95, 100, 110);
constexpr QRgb kMarkColour = qRgb(240, 170, 30);
constexpr QRgb kConnectorColour = qRgb(45, 45, 50);
constexpr QRgb kEdgeColour = qRgb(30, 35, 45);

Vector3d groundPoint(double x, double y)
{
    return Vector3d(x, y, kGroundZ);
}

// The navigation axes of the display frame (ENU, NWU or NED) in the ENU scene, drawn from the
// grid's south-west corner.
std::array<Vector3d, 3> navigationTriad(AttitudeWidget::DisplayFrame frame, model::WorldFrame world)
{
    if (frame == AttitudeWidget::DisplayFrame::Ned)
        return {Vector3d::UnitY(), Vector3d::UnitX(), -Vector3d::UnitZ()};
    if (world == model::WorldFrame::Nwu)
        return {Vector3d::UnitY(), -Vector3d::UnitX(), Vector3d::UnitZ()};
    return {Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()};
}

// Box: vertex i has x sign bit 0, y sign bit 1, z sign bit 2 (set = +).
struct Face {
    std::array<int, 4> v; // counter-clockwise seen from outside
    int axis;             // 0, 1, 2
    int sign;             // +1 / -1
};
constexpr std::array<Face, 6> kFaces{{
    {{1, 3, 7, 5}, 0, +1},
    {{0, 4, 6, 2}, 0, -1},
    {{2, 6, 7, 3}, 1, +1},
    {{0, 1, 5, 4}, 1, -1},
    {{4, 5, 7, 6}, 2, +1},
    {{0, 2, 3, 1}, 2, -1},
}};
constexpr int kTopFace = 4;

// Top-face print: an arrow pointing forward (+Y) and the connector along the back edge.
constexpr std::array<std::array<double, 2>, 7> kForwardMark{{
    {-0.14, -0.45}, {0.14, -0.45}, {0.14, 0.15}, {0.38, 0.15}, {0.0, 0.72}, {-0.38, 0.15}, {-0.14, 0.15},
}};
constexpr std::array<std::array<double, 2>, 4> kConnector{{{-0.55, -0.93}, {0.55, -0.93}, {0.55, -0.68}, {-0.55, -0.68}}};

QColor shaded(QRgb base, double factor, bool grey)
{
    QColor c = QColor::fromRgb(base);
    if (grey) {
        const int g = qGray(base);
        c = QColor(g, g, g);
    }
    factor = std::clamp(factor, 0.0, 1.2);
    return QColor(std::min(255, int(c.red() * factor)), std::min(255, int(c.green() * factor)),
                  std::min(255, int(c.blue() * factor)));
}

QColor greyed(QRgb colour, bool grey)
{
    if (!grey)
        return QColor::fromRgb(colour);
    const int g = std::min(200, qGray(colour) + 40);
    return QColor(g, g, g);
}

QString formatAngle(const QLocale &locale, double deg)
{
    if (std::abs(deg) < 0.05)
        deg = 0; // never "-0.0"
    return locale.toString(deg, 'f', 1) + QChar(0x00B0);
}

// Points on a ray from `from` through `to`, `pixels` beyond `to`.
QPointF beyond(const QPointF &from, const QPointF &to, double pixels)
{
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1e-6)
        return to + QPointF(0, -pixels);
    return to + d * (pixels / len);
}

// A label centred on `at`, on a translucent plate so that it reads over the module too.
void drawLabel(QPainter &p, const QPointF &at, const QStaticText &text, const QColor &colour, const QColor &plate)
{
    const QSizeF s = text.size();
    const QPointF topLeft = at - QPointF(s.width() / 2, s.height() / 2);
    p.setPen(Qt::NoPen);
    p.setBrush(plate);
    p.drawRoundedRect(QRectF(topLeft, s).adjusted(-2, 0, 2, 0), 3, 3);
    p.setPen(colour);
    p.drawStaticText(topLeft, text);
}

} // namespace

// Camera and projection for one paint.
struct AttitudeWidget::View {
    Vector3d eye, right, up, forward, toCamera;
    Vector3d light; // unit vector towards the light
    double focal = 1, cx = 0, cy = 0;
    Eigen::Matrix3d body; // body -> ENU
    bool grey = false;

    View(double azimuthDeg, double elevationDeg, const QRectF &area, const model::Quat &q, bool noData)
    {
        const double a = azimuthDeg * model::kDegToRad, e = elevationDeg * model::kDegToRad;
        toCamera = Vector3d(std::sin(a) * std::cos(e), std::cos(a) * std::cos(e), std::sin(e));
        eye = Vector3d(0, 0, kTargetZ) + kCameraDistance * toCamera;
        forward = -toCamera;
        right = forward.cross(Vector3d::UnitZ()).normalized();
        up = right.cross(forward);
        // Light from the upper left of the camera, fixed to the camera so orbiting keeps the look.
        light = (-0.35 * right + 0.75 * up + 0.55 * toCamera).normalized();
        cx = area.center().x();
        cy = area.center().y();
        focal = 0.5 * std::min(area.width(), area.height()) * kCameraDistance / kFitRadius;
        body = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
        grey = noData;
    }

    double depth(const Vector3d &p) const { return (p - eye).dot(forward); }

    QPointF project(const Vector3d &p) const
    {
        const Vector3d d = p - eye;
        const double z = std::max(d.dot(forward), 1e-3);
        return QPointF(cx + focal * d.dot(right) / z, cy - focal * d.dot(up) / z);
    }

    Vector3d bodyPoint(double x, double y, double z) const { return body * Vector3d(x, y, z); }
};

AttitudeWidget::AttitudeWidget(QWidget *parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(false);
    setCursor(Qt::OpenHandCursor);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    retranslate();
}

AttitudeWidget::~AttitudeWidget() = default;

void AttitudeWidget::setQuaternion(const model::Quat &q)
{
    if (!model::isUsableQuat(q))
        return;
    if (m_hasData && q == m_input)
        return;
    m_input = q;
    m_quat = inScene(q);
    m_hasData = true;
    updateReadouts();
    update();
}

void AttitudeWidget::clear()
{
    if (!m_hasData)
        return;
    m_hasData = false;
    m_input = model::Quat{};
    m_quat = model::Quat{};
    updateReadouts();
    update();
}

void AttitudeWidget::setGhost(const model::Quat &q, const QString &caption)
{
    if (!model::isUsableQuat(q))
        return;
    m_ghost = inScene(q);
    m_ghostCaption = caption;
    m_ghostShown = true;
    update();
}

void AttitudeWidget::setGhostShown(bool shown)
{
    if (shown == m_ghostShown)
        return;
    m_ghostShown = shown;
    if (!shown) {
        m_ghostCaption.clear();
        m_ghostTrace.clear();
    }
    update();
}

void AttitudeWidget::addGhostDifference(double tS, double apartDeg)
{
    if (!std::isfinite(tS) || !std::isfinite(apartDeg) || (!m_ghostTrace.empty() && tS <= m_ghostTrace.back().x()))
        return;
    m_ghostTrace.emplace_back(tS, apartDeg);
    size_t drop = 0;
    while (drop < m_ghostTrace.size() && (tS - m_ghostTrace[drop].x() > kGhostTraceS || m_ghostTrace.size() - drop > kGhostTraceMax))
        ++drop;
    m_ghostTrace.erase(m_ghostTrace.begin(), m_ghostTrace.begin() + std::ptrdiff_t(drop));
}

void AttitudeWidget::paintGhost(QPainter &p) const
{
    if (!m_ghostShown || !m_hasData)
        return;
    const View g(m_azimuth, m_elevation, modelArea(), m_ghost, false);
    QColor pen = palette().color(QPalette::Highlight);
    p.save();
    p.setPen(QPen(pen, 2.0, Qt::DashLine, Qt::RoundCap));
    p.setBrush(Qt::NoBrush);
    // The box's twelve edges: corners that differ in one coordinate.
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit)) {
                const int j = i | bit;
                auto corner = [&g](int k) {
                    return g.project(g.bodyPoint(k & 1 ? kHalfX : -kHalfX, k & 2 ? kHalfY : -kHalfY, k & 4 ? kHalfZ : -kHalfZ));
                };
                p.drawLine(corner(i), corner(j));
            }
    // Its forward (+Y) axis, as the module's nose.
    p.setPen(QPen(pen, 2.0, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(g.project(g.bodyPoint(0, 0, 0)), g.project(g.bodyPoint(0, kHalfY + 0.8, 0)));
    if (!m_ghostCaption.isEmpty()) {
        const QRectF scene = sceneRect();
        const QFontMetricsF fm(font());
        const QRectF box(scene.left() + kPanelMargin, scene.bottom() - fm.height() - 2 * kPanelMargin,
                         fm.horizontalAdvance(m_ghostCaption) + 2 * kPanelPadding, fm.height() + kPanelPadding);
        QColor plate = palette().color(QPalette::Base);
        plate.setAlphaF(0.8);
        p.fillRect(box, plate);
        p.setPen(pen);
        p.drawText(box, Qt::AlignCenter, m_ghostCaption);
        // The last kGhostTraceS of the angle apart, above the caption across the scene: 0 at the
        // bottom, the largest angle (at least 1°) at the top, now at the right edge.
        if (m_ghostTrace.size() >= 2) {
            const double h = 2.5 * fm.height();
            const QRectF chart(scene.left() + kPanelMargin, box.top() - h - kPanelMargin / 2,
                               std::max(40.0, scene.width() - 2 * kPanelMargin), h);
            p.fillRect(chart, plate);
            double top = 1.0;
            for (const QPointF &v : m_ghostTrace)
                top = std::max(top, v.y());
            const double now = m_ghostTrace.back().x();
            QPolygonF line;
            for (const QPointF &v : m_ghostTrace)
                line << QPointF(chart.right() - (now - v.x()) / kGhostTraceS * chart.width(),
                                chart.bottom() - v.y() / top * chart.height());
            p.setPen(QPen(pen, 1.5));
            p.drawPolyline(line);
            p.setPen(QPen(pen, 0));
            p.drawRect(chart);
            p.drawText(chart.adjusted(4, 2, -4, 0), Qt::AlignTop | Qt::AlignLeft,
                       tr("%1° in %2 s").arg(top, 0, 'f', 1).arg(kGhostTraceS, 0, 'f', 0));
        }
    }
    p.restore();
}

model::Quat AttitudeWidget::inScene(const model::Quat &q) const
{
    return m_world == model::WorldFrame::Nwu ? model::nwuToEnu(q) : model::normalized(q);
}

QString AttitudeWidget::ownFrameTitle() const
{
    if (m_worldAssumed)
        return m_world == model::WorldFrame::Nwu ? tr("NWU 3-1-2 (assumed)") : tr("ENU 3-1-2 (assumed)");
    return m_world == model::WorldFrame::Nwu ? tr("NWU 3-1-2") : tr("ENU 3-1-2");
}

QString AttitudeWidget::frameWarning() const
{
    if (!m_worldAssumed)
        return QString();
    return tr("World frame assumed %1: the module's LOG COMCONFIG reply names no COORD")
        .arg(QLatin1String(model::worldFrameName(m_world)));
}

void AttitudeWidget::setWorldFrame(model::WorldFrame frame, bool assumed)
{
    if (frame == m_world && assumed == m_worldAssumed)
        return;
    m_world = frame;
    m_worldAssumed = assumed;
    setToolTip(frameWarning().isEmpty() ? tr("Drag to turn the view, double-click to reset it")
                                        : frameWarning() + QLatin1Char('\n') + tr("Drag to turn the view, double-click to reset it"));
    if (m_hasData)
        m_quat = inScene(m_input);
    retranslate();
    update();
}

void AttitudeWidget::setDisplayFrame(DisplayFrame frame)
{
    if (frame == m_frame)
        return;
    m_frame = frame;
    retranslate();
    update();
    Q_EMIT displayFrameChanged(frame);
}

void AttitudeWidget::setCameraAngles(double azimuthDeg, double elevationDeg)
{
    if (!std::isfinite(azimuthDeg) || !std::isfinite(elevationDeg))
        return;
    const double az = model::wrap360(azimuthDeg);
    const double el = std::clamp(elevationDeg, -kMaxElevationDeg, kMaxElevationDeg);
    if (az == m_azimuth && el == m_elevation)
        return;
    m_azimuth = az;
    m_elevation = el;
    update();
}

void AttitudeWidget::resetCamera()
{
    setCameraAngles(kDefaultAzimuthDeg, kDefaultElevationDeg);
}

QString AttitudeWidget::readoutText() const
{
    if (!m_hasData)
        return m_noDataText;
    QString text = m_frameTitle;
    if (m_worldAssumed)
        text += QLatin1Char('\n') + frameWarning();
    for (size_t i = 0; i < m_readoutNames.size(); ++i)
        text += QLatin1Char('\n') + m_readoutNames[i] + QLatin1Char(' ') + m_readoutValues[i];
    return text;
}

QPointF AttitudeWidget::screenPosition(const model::Vec3 &enu) const
{
    const View v(m_azimuth, m_elevation, modelArea(), m_quat, !m_hasData);
    return v.project(Vector3d(enu.x, enu.y, enu.z));
}

QRectF AttitudeWidget::sceneRect() const
{
    const double w = width(), h = height();
    const QRectF beside(m_panel.right() + kPanelMargin, 0, std::max(1.0, w - m_panel.right() - kPanelMargin), h);
    const QRectF below(0, m_panel.bottom() + kPanelMargin, w, std::max(1.0, h - m_panel.bottom() - kPanelMargin));
    const auto fit = [](const QRectF &r) { return std::min(r.width(), r.height()); };
    return fit(beside) >= fit(below) ? beside : below;
}

QRectF AttitudeWidget::modelArea() const
{
    // The world axes' names stand beyond the grid's corners: keep room for them at the sides,
    // so that "U (z)" is never cut at the edge.
    double label = 0;
    for (const QStaticText &t : m_worldLabels)
        label = std::max(label, t.size().width());
    const QRectF scene = sceneRect();
    const double inset = std::min(0.6 * label, 0.15 * scene.width());
    return scene.adjusted(inset, 0, -inset, 0);
}

QSize AttitudeWidget::sizeHint() const
{
    return QSize(420, 340);
}

QSize AttitudeWidget::minimumSizeHint() const
{
    return QSize(200, 130); // the model and its read-out side by side, on a short laptop screen too
}

void AttitudeWidget::retranslate()
{
    m_axisLabels[0].setText(tr("X"));
    m_axisLabels[1].setText(tr("Y"));
    m_axisLabels[2].setText(tr("Z"));
    m_northLabel.setText(tr("N"));
    if (m_frame == DisplayFrame::Enu && m_world == model::WorldFrame::Nwu) {
        m_worldLabels[0].setText(tr("N (x)"));
        m_worldLabels[1].setText(tr("W (y)"));
        m_worldLabels[2].setText(tr("U (z)"));
        m_frameTitle = ownFrameTitle();
    } else if (m_frame == DisplayFrame::Enu) {
        m_worldLabels[0].setText(tr("E (x)"));
        m_worldLabels[1].setText(tr("N (y)"));
        m_worldLabels[2].setText(tr("U (z)"));
        m_frameTitle = ownFrameTitle();
    } else {
        m_worldLabels[0].setText(tr("N (x)"));
        m_worldLabels[1].setText(tr("E (y)"));
        m_worldLabels[2].setText(tr("D (z)"));
        m_frameTitle = m_worldAssumed ? tr("NED 3-2-1 (assumed)") : tr("NED 3-2-1");
    }
    m_noDataText = tr("No attitude yet");
    m_readoutNames = {tr("Roll"), tr("Pitch"), tr("Yaw"), tr("Heading")};
    setToolTip(frameWarning().isEmpty() ? tr("Drag to turn the view, double-click to reset it")
                                        : frameWarning() + QLatin1Char('\n') + tr("Drag to turn the view, double-click to reset it"));
    const QFont normal = font();
    m_boldFont = normal;
    m_boldFont.setBold(true);
    for (QStaticText *t : {&m_worldLabels[0], &m_worldLabels[1], &m_worldLabels[2], &m_northLabel}) {
        t->setTextFormat(Qt::PlainText);
        t->prepare(QTransform(), normal);
    }
    for (QStaticText &t : m_axisLabels) {
        t.setTextFormat(Qt::PlainText);
        t.prepare(QTransform(), m_boldFont);
    }
    m_noDataStatic = QStaticText(m_noDataText);
    m_noDataStatic.setTextFormat(Qt::PlainText);
    m_noDataStatic.prepare(QTransform(), normal);

    // Read-out panel: the bold title, then name / value rows. Laid out here, not per paint.
    m_titleStatic = QStaticText(m_frameTitle);
    m_titleStatic.setTextFormat(Qt::PlainText);
    m_titleStatic.prepare(QTransform(), m_boldFont);
    const QFontMetricsF fm(normal);
    double nameWidth = 0;
    for (size_t i = 0; i < m_readoutNames.size(); ++i) {
        m_nameStatic[i] = QStaticText(m_readoutNames[i]);
        m_nameStatic[i].setTextFormat(Qt::PlainText);
        m_nameStatic[i].prepare(QTransform(), normal);
        nameWidth = std::max(nameWidth, m_nameStatic[i].size().width());
    }
    const double valueWidth = fm.horizontalAdvance(QStringLiteral("-000.0\u00b0"));
    const double contentWidth = std::max(nameWidth + 12 + valueWidth, m_titleStatic.size().width());
    m_lineSpacing = fm.lineSpacing();
    m_panel = QRectF(kPanelMargin, kPanelMargin, 2 * kPanelPadding + contentWidth,
                     2 * kPanelPadding + m_lineSpacing * 4 + fm.height());
    updateReadouts();
}

void AttitudeWidget::updateReadouts()
{
    if (!m_hasData) {
        m_readoutValues.fill(QString());
        return;
    }
    const model::Euler e = m_frame == DisplayFrame::Ned ? model::eulerNed321(model::enuToNed(m_quat))
        : m_world == model::WorldFrame::Nwu      ? model::eulerEnu312(model::enuToNwu(m_quat)) // 3-1-2 in NWU
                                                 : model::eulerEnu312(m_quat);
    double heading = model::headingDeg(m_quat);
    if (heading >= 359.95)
        heading = 0; // would print as 360.0
    const QLocale loc = locale();
    m_readoutValues = {formatAngle(loc, e.roll), formatAngle(loc, e.pitch), formatAngle(loc, e.yaw),
                       formatAngle(loc, heading)};
    // Prepared once per new value (refresh clock), drawn by every paint.
    for (size_t i = 0; i < m_readoutValues.size(); ++i) {
        m_valueStatic[i] = QStaticText(m_readoutValues[i]);
        m_valueStatic[i].setTextFormat(Qt::PlainText);
        m_valueStatic[i].prepare(QTransform(), font());
    }
}

void AttitudeWidget::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);

    const View v(m_azimuth, m_elevation, modelArea(), m_quat, !m_hasData);
    // Painter's algorithm: ground, far half of the axes, body faces back to front, near
    // half of the axes, then all labels and the read-outs on top. With the camera under
    // the ground plane the ground is in front of the module.
    const bool groundBehind = v.eye.z() > kGroundZ;
    if (groundBehind) {
        paintCachedGround(p, v);
        paintShadow(p, v);
    } else {
        p.fillRect(rect(), palette().color(QPalette::Base));
    }
    paintAxes(p, v, false, false);
    paintBody(p, v);
    paintAxes(p, v, true, false);
    if (!groundBehind)
        paintGround(p, v, false);
    paintGround(p, v, true);
    paintAxes(p, v, false, true);
    paintGhost(p);
    paintReadouts(p);
}

void AttitudeWidget::paintGround(QPainter &p, const View &v, bool labels) const
{
    if (labels) {
        const QColor ink = palette().color(QPalette::Text);
        const double g = kGridHalf;
        const Vector3d triadOrigin = groundPoint(-g, -g);
        const std::array<Vector3d, 3> triad = navigationTriad(m_frame, m_world);
        QColor plate = palette().color(QPalette::Base);
        plate.setAlphaF(0.6);
        drawLabel(p, v.project(groundPoint(0, g + 0.55)), m_northLabel, ink, plate);
        QColor soft = ink;
        soft.setAlphaF(0.75);
        for (int i = 0; i < 3; ++i) {
            const QPointF a = v.project(triadOrigin), b = v.project(triadOrigin + kTriadLength * triad[i]);
            const QSizeF s = m_worldLabels[i].size();
            drawLabel(p, beyond(a, b, 4 + 0.5 * std::max(s.width(), s.height())), m_worldLabels[i], soft, plate);
        }
        return;
    }
    paintGroundLines(p, v);
    paintShadow(p, v);
}

void AttitudeWidget::paintGroundLines(QPainter &p, const View &v) const
{
    const QColor ink = palette().color(QPalette::Text);
    const double g = kGridHalf;
    const Vector3d triadOrigin = groundPoint(-g, -g);
    const std::array<Vector3d, 3> triad = navigationTriad(m_frame, m_world);

    // Grid: opaque and cosmetic: drawn pixel by pixel, not blended as a path.
    p.setPen(QPen(mixColours(palette().color(QPalette::Base), ink, 0.18), 0));
    for (int i = -kGridHalf; i <= kGridHalf; ++i) {
        p.drawLine(v.project(groundPoint(i, -g)), v.project(groundPoint(i, g)));
        p.drawLine(v.project(groundPoint(-g, i)), v.project(groundPoint(g, i)));
    }

    // North arrow on the ground, from the centre to the grid's north edge.
    QColor north = ink;
    north.setAlphaF(0.7);
    p.setPen(QPen(north, 2.0, Qt::SolidLine, Qt::FlatCap));
    p.drawLine(v.project(groundPoint(0, 0)), v.project(groundPoint(0, g - 0.8)));
    const std::array<QPointF, 3> head{v.project(groundPoint(-0.35, g - 0.8)), v.project(groundPoint(0.35, g - 0.8)),
                                      v.project(groundPoint(0, g))};
    p.setPen(Qt::NoPen);
    p.setBrush(north);
    p.drawConvexPolygon(head.data(), 3);

    // Navigation-frame triad.
    p.setPen(QPen(north, 1.5, Qt::SolidLine, Qt::RoundCap));
    for (int i = 0; i < 3; ++i)
        p.drawLine(v.project(triadOrigin), v.project(triadOrigin + kTriadLength * triad[i]));
}

void AttitudeWidget::paintShadow(QPainter &p, const View &v) const
{
    // Shadow of the module straight down: convex hull of the 8 corners dropped on the ground.
    std::array<QPointF, 8> pts;
    for (int i = 0; i < 8; ++i) {
        const Vector3d c = v.bodyPoint(i & 1 ? kHalfX : -kHalfX, i & 2 ? kHalfY : -kHalfY, i & 4 ? kHalfZ : -kHalfZ);
        pts[i] = v.project(groundPoint(c.x(), c.y()));
    }
    std::sort(pts.begin(), pts.end(),
              [](const QPointF &a, const QPointF &b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
    const auto cross = [](const QPointF &o, const QPointF &a, const QPointF &b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::array<QPointF, 16> hull;
    int k = 0;
    for (int i = 0; i < 8; ++i) { // monotone chain, lower then upper hull
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0)
            --k;
        hull[k++] = pts[i];
    }
    for (int i = 6, t = k + 1; i >= 0; --i) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0)
            --k;
        hull[k++] = pts[i];
    }
    if (k > 3) {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0, 0, 0, 38));
        p.drawConvexPolygon(hull.data(), k - 1);
    }
}

void AttitudeWidget::paintCachedGround(QPainter &p, const View &v) const
{
    const QPalette pal = palette();
    const GroundKey key{size(), devicePixelRatioF(), m_azimuth, m_elevation, m_frame, m_world, m_hasData,
                        pal.color(QPalette::Base).rgb(), pal.color(QPalette::Text).rgb()};
    if (m_ground.isNull() || !(key == m_groundKey)) {
        m_ground = QPixmap(size() * key.dpr);
        m_ground.setDevicePixelRatio(key.dpr);
        m_ground.fill(pal.color(QPalette::Base));
        QPainter gp(&m_ground);
        gp.setRenderHint(QPainter::Antialiasing);
        paintGroundLines(gp, v);
        m_groundKey = key;
    }
    p.drawPixmap(0, 0, m_ground);
}

void AttitudeWidget::paintBody(QPainter &p, const View &v) const
{
    std::array<Vector3d, 8> corners;
    std::array<QPointF, 8> screen;
    for (int i = 0; i < 8; ++i) {
        corners[i] = v.bodyPoint(i & 1 ? kHalfX : -kHalfX, i & 2 ? kHalfY : -kHalfY, i & 4 ? kHalfZ : -kHalfZ);
        screen[i] = v.project(corners[i]);
    }
    const std::array<double, 3> half{kHalfX, kHalfY, kHalfZ};

    // Visible faces (facing the eye; perspective, so test against the face's centre).
    struct Visible {
        int face;
        double depth;
        double light;
    };
    std::array<Visible, 6> visible;
    int count = 0;
    for (int f = 0; f < 6; ++f) {
        const Face &face = kFaces[f];
        const Vector3d normal = face.sign * v.body.col(face.axis);
        const Vector3d centre = normal * half[face.axis];
        if (normal.dot(v.eye - centre) <= 0)
            continue;
        visible[count++] = Visible{f, v.depth(centre), normal.dot(v.light)};
    }
    // Farthest first (at most three faces: an insertion sort).
    for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && visible[j - 1].depth < visible[j].depth; --j)
            std::swap(visible[j - 1], visible[j]);

    const QPen edgePen(greyed(kEdgeColour, v.grey), 1.2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    for (int n = 0; n < count; ++n) {
        const Face &face = kFaces[visible[n].face];
        const double shade = 0.45 + 0.6 * std::max(0.0, visible[n].light);
        const QRgb base = face.axis == 2 ? (face.sign > 0 ? kTopColour : kBottomColour) : kSideColour;
        const std::array<QPointF, 4> poly{screen[face.v[0]], screen[face.v[1]], screen[face.v[2]], screen[face.v[3]]};
        p.setPen(edgePen);
        p.setBrush(shaded(base, shade, v.grey));
        p.drawConvexPolygon(poly.data(), 4);

        if (visible[n].face != kTopFace)
            continue;
        // The print on the top face: only visible when the top faces the camera, so an
        // upside-down module is obvious.
        const double z = kHalfZ;
        std::array<QPointF, 4> conn;
        for (size_t i = 0; i < kConnector.size(); ++i)
            conn[i] = v.project(v.bodyPoint(kConnector[i][0], kConnector[i][1], z));
        p.setPen(Qt::NoPen);
        p.setBrush(shaded(kConnectorColour, shade, v.grey));
        p.drawConvexPolygon(conn.data(), 4);
        std::array<QPointF, 7> mark;
        for (size_t i = 0; i < kForwardMark.size(); ++i)
            mark[i] = v.project(v.bodyPoint(kForwardMark[i][0], kForwardMark[i][1], z));
        p.setBrush(shaded(kMarkColour, 0.55 + 0.5 * shade, v.grey));
        p.drawPolygon(mark.data(), 7);
    }
}

void AttitudeWidget::paintAxes(QPainter &p, const View &v, bool nearSide, bool labels) const
{
    const QPointF origin = v.project(Vector3d::Zero());
    const double originDepth = v.depth(Vector3d::Zero());
    QColor plate = palette().color(QPalette::Base);
    plate.setAlphaF(0.7);
    for (int i = 0; i < 3; ++i) {
        const Vector3d tip3 = kAxisLength[i] * v.body.col(i);
        const QPointF tip = v.project(tip3);
        const QColor colour = greyed(kAxisColours[i], v.grey);
        if (labels) {
            const QSizeF s = m_axisLabels[i].size();
            p.setFont(m_boldFont);
            drawLabel(p, beyond(origin, tip, 5 + 0.5 * std::max(s.width(), s.height())), m_axisLabels[i], colour,
                      plate);
            p.setFont(font());
            continue;
        }
        if ((v.depth(tip3) < originDepth) != nearSide)
            continue;
        p.setPen(QPen(colour, 2.5, Qt::SolidLine, Qt::RoundCap));
        const QPointF d = tip - origin;
        const double len = std::hypot(d.x(), d.y());
        if (len < 2.0) { // pointing at the camera: a dot
            p.setBrush(colour);
            p.drawEllipse(tip, 3.0, 3.0);
            continue;
        }
        const QPointF dir = d / len, normal(-dir.y(), dir.x());
        const double headLen = std::min(12.0, 0.45 * len), headHalf = 0.42 * headLen;
        const QPointF base = tip - dir * headLen;
        p.drawLine(origin, base);
        const std::array<QPointF, 3> head{tip, base + normal * headHalf, base - normal * headHalf};
        p.setPen(QPen(colour, 1.0));
        p.setBrush(colour);
        p.drawConvexPolygon(head.data(), 3);
    }
}

void AttitudeWidget::paintReadouts(QPainter &p) const
{
    const QColor ink = palette().color(QPalette::Text);
    if (!m_hasData) {
        QColor grey = ink;
        grey.setAlphaF(0.6);
        p.setPen(grey);
        const QRectF scene = sceneRect();
        p.drawStaticText(QPointF(scene.center().x() - m_noDataStatic.size().width() / 2, kPanelMargin),
                         m_noDataStatic);
        return;
    }
    // Beside the model, never over it: an opaque box, drawn without antialiasing (a plain
    // rectangle fill, not a blended path: cheap at the refresh rate).
    const QColor back = palette().color(QPalette::Base);
    p.save();
    p.setRenderHint(QPainter::Antialiasing, false);
    p.fillRect(m_panel, back);
    p.setPen(QPen(mixColours(back, ink, 0.25), 0));
    p.setBrush(Qt::NoBrush);
    p.drawRect(m_panel.toAlignedRect().adjusted(0, 0, -1, -1));
    p.restore();

    p.setPen(ink);
    const double left = m_panel.left() + kPanelPadding, right = m_panel.right() - kPanelPadding;
    double y = m_panel.top() + kPanelPadding;
    p.setFont(m_boldFont);
    p.drawStaticText(QPointF(left, y), m_titleStatic);
    p.setFont(font());
    for (size_t i = 0; i < m_nameStatic.size(); ++i) {
        y += m_lineSpacing;
        p.drawStaticText(QPointF(left, y), m_nameStatic[i]);
        p.drawStaticText(QPointF(right - m_valueStatic[i].size().width(), y), m_valueStatic[i]);
    }
    if (m_worldAssumed) {
        // The frame is ImuDesk's assumption, not the module's word: said under the scene, in amber.
        p.setPen(QColor(0xb0, 0x60, 0x00));
        p.drawText(QRectF(rect()).adjusted(kPanelMargin, 0, -kPanelMargin, -kPanelMargin),
                   Qt::AlignLeft | Qt::AlignBottom | Qt::TextWordWrap, frameWarning());
    }
}

void AttitudeWidget::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton) {
        m_dragging = true;
        m_lastMouse = event->position();
        setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void AttitudeWidget::mouseMoveEvent(QMouseEvent *event)
{
    if (!m_dragging || !(event->buttons() & Qt::LeftButton)) {
        QWidget::mouseMoveEvent(event);
        return;
    }
    const QPointF d = event->position() - m_lastMouse;
    m_lastMouse = event->position();
    // Dragging right turns the scene like grabbing it: the camera moves clockwise.
    setCameraAngles(m_azimuth + kDragDegPerPixel * d.x(), m_elevation + kDragDegPerPixel * d.y());
    event->accept();
}

void AttitudeWidget::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && m_dragging) {
        m_dragging = false;
        setCursor(Qt::OpenHandCursor);
        event->accept();
        return;
    }
    QWidget::mouseReleaseEvent(event);
}

void AttitudeWidget::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton) {
        resetCamera();
        event->accept();
        return;
    }
    QWidget::mouseDoubleClickEvent(event);
}

void AttitudeWidget::contextMenuEvent(QContextMenuEvent *event)
{
    QMenu menu(this);
    auto *group = new QActionGroup(&menu);
    QAction *enu = menu.addAction(ownFrameTitle());
    QAction *ned = menu.addAction(tr("NED 3-2-1"));
    for (QAction *a : {enu, ned}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    enu->setChecked(m_frame == DisplayFrame::Enu);
    ned->setChecked(m_frame == DisplayFrame::Ned);
    menu.addSeparator();
    QAction *ghost = menu.addAction(tr("Show ImuDesk's reference attitude"));
    ghost->setCheckable(true);
    ghost->setChecked(m_ghostShown);
    ghost->setToolTip(tr("ImuDesk's own filter on the module's raw gyro and accelerometer, drawn as an outline: "
                         "started from the module's heading when it last rested for 1 s"));
    QAction *reset = menu.addAction(tr("Reset view"));
    QAction *chosen = menu.exec(event->globalPos());
    if (chosen == ghost)
        Q_EMIT ghostRequested(ghost->isChecked());
    if (chosen == enu)
        setDisplayFrame(DisplayFrame::Enu);
    else if (chosen == ned)
        setDisplayFrame(DisplayFrame::Ned);
    else if (chosen == reset)
        resetCamera();
}

void AttitudeWidget::changeEvent(QEvent *event)
{
    switch (event->type()) {
    case QEvent::LanguageChange:
    case QEvent::FontChange:
    case QEvent::LocaleChange:
        retranslate();
        update();
        break;
    case QEvent::PaletteChange:
        update();
        break;
    default:
        break;
    }
    QWidget::changeEvent(event);
}

} // namespace imudesk::ui
