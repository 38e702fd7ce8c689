#include "charts/chart_view.h"

#include "plot/channel_catalog.h"

#include "charts/plot_canvas.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFont>
#include <QFrame>
#include <QHBoxLayout>
#include <QImageWriter>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPainter>
#include <QPen>
#include <QPixmap>
#include <QPushButton>
#include <QVBoxLayout>
#include <QWidgetAction>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

using plot::Channel;
using plot::TimeAxis;

namespace {

struct KindTraits {
    double fixedMin, fixedMax; // default fixed range
    double minSpan;            // smallest autoscaled span
    int spinDecimals;
    int valueDecimals;         // crosshair read-out
    const char *fileStem;      // default PNG name
};

constexpr std::array<KindTraits, kChartKindCount> kTraits = {{
    {-2.0, 2.0, 0.002, 3, 4, "accelerometer"},
    {-250.0, 250.0, 0.02, 1, 3, "gyroscope"},
    {-100.0, 100.0, 0.2, 1, 2, "magnetometer"},
    {-180.0, 180.0, 0.02, 1, 2, "euler"},
    {-1.0, 1.0, 0.0002, 3, 4, "quaternion"},
    {95000.0, 105000.0, 2.0, 0, 1, "pressure"},
    {-20.0, 60.0, 0.02, 1, 2, "temperature"},
    {-2.0, 2.0, 0.002, 3, 3, "magnetic_relative"},
}};

const KindTraits &traits(ChartKind kind)
{
    return kTraits[size_t(kind)];
}

} // namespace

// ---------------------------------------------------------------- static helpers

std::vector<Channel> ChartView::channelsOf(ChartKind kind)
{
    static_assert(int(plot::ChannelGroup::Temperature) == int(ChartKind::Temperature)
                      && int(plot::ChannelGroup::MagneticRelative) == int(ChartKind::MagneticRelative)
                      && plot::kChannelGroupCount == kChartKindCount,
                  "one chart per channel group, in the same order");
    return plot::channelsOf(plot::ChannelGroup(kind));
}

uint32_t ChartView::channelMask(ChartKind kind)
{
    uint32_t mask = 0;
    for (Channel c : channelsOf(kind))
        mask |= plot::channelBit(c);
    return mask;
}

ChartKind ChartView::kindOf(Channel channel)
{
    return ChartKind(plot::channelInfo(channel).group); // the same order (channelsOf)
}

QString ChartView::title(ChartKind kind)
{
    switch (kind) {
    case ChartKind::Accelerometer: return tr("Accelerometer");
    case ChartKind::Gyroscope: return tr("Gyroscope");
    case ChartKind::Magnetometer: return tr("Magnetometer");
    case ChartKind::Euler: return tr("Euler angles");
    case ChartKind::Quaternion: return tr("Quaternion");
    case ChartKind::Pressure: return tr("Air pressure");
    case ChartKind::Temperature: return tr("Temperature");
    case ChartKind::MagneticRelative: return tr("Relative magnetic field");
    }
    return {};
}

QString ChartView::quantity(ChartKind kind)
{
    switch (kind) {
    case ChartKind::Accelerometer: return tr("Acceleration");
    case ChartKind::Gyroscope: return tr("Angular velocity");
    case ChartKind::Magnetometer: return tr("Magnetic field");
    case ChartKind::Euler: return tr("Angle");
    case ChartKind::Quaternion: return tr("Quaternion component");
    case ChartKind::Pressure: return tr("Pressure");
    case ChartKind::Temperature: return tr("Temperature");
    case ChartKind::MagneticRelative: return tr("Magnetic field (north = 1)");
    }
    return {};
}

QString ChartView::unit(ChartKind kind)
{
    switch (kind) {
    case ChartKind::Accelerometer: return tr("G");
    case ChartKind::Gyroscope: return tr("deg/s");
    case ChartKind::Magnetometer: return tr("µT");
    case ChartKind::Euler: return tr("deg");
    case ChartKind::Quaternion: return QString();
    case ChartKind::Pressure: return tr("Pa");
    case ChartKind::Temperature: return tr("°C");
    case ChartKind::MagneticRelative: return QString(); // relative: the horizontal northward field is 1
    }
    return {};
}

QString ChartView::axisName(Channel channel)
{
    const plot::ChannelInfo &i = plot::channelInfo(channel);
    return *i.axis ? QLatin1String(i.axis) : plot::channelName(channel);
}

QString ChartView::channelName(Channel channel)
{
    return plot::channelName(channel);
}

QColor ChartView::colour(Channel channel)
{
    return QColor::fromRgb(QRgb(plot::channelInfo(channel).rgb));
}

int ChartView::valueDecimals(ChartKind kind)
{
    return traits(kind).valueDecimals;
}

QString ChartView::timeAxisTitle(TimeAxis axis)
{
    return axis == TimeAxis::Device ? tr("Device time (s)") : tr("Common time (s)");
}

QString ChartView::windowText(double seconds)
{
    if (seconds >= 60.0)
        return tr("%1 min").arg(seconds / 60.0);
    return tr("%1 s").arg(seconds);
}

void ChartView::fillWindowCombo(QComboBox *combo, double selected)
{
    const QSignalBlocker blocker(combo);
    combo->clear();
    for (double s : ChartSettings::kWindowChoices) {
        combo->addItem(windowText(s), s);
        if (s == selected)
            combo->setCurrentIndex(combo->count() - 1);
    }
}

QComboBox *ChartView::makeWindowChooser(QWidget *parent, double selected, QLabel *&label,
                                        const std::function<void(double)> &chosen)
{
    label = new QLabel(parent);
    auto *combo = new QComboBox(parent);
    combo->setObjectName(QStringLiteral("windowCombo"));
    label->setBuddy(combo);
    fillWindowCombo(combo, selected);
    QObject::connect(combo, &QComboBox::currentIndexChanged, parent,
                     [combo, chosen](int) { chosen(combo->currentData().toDouble()); });
    return combo;
}

bool ChartView::saveWidgetPng(QWidget *widget, const QString &path, QString *error)
{
    const QImage image = widget->grab().toImage();
    QImageWriter writer(path, "png");
    if (image.isNull() || !writer.write(image)) {
        if (error) {
            const QString why = image.isNull() ? tr("the chart could not be drawn") : writer.errorString();
            *error = tr("Could not save the chart as %1: %2").arg(QDir::toNativeSeparators(path), why);
        }
        return false;
    }
    return true;
}

// ---------------------------------------------------------------- the widget

ChartView::ChartView(ChartKind kind, QWidget *parent)
    : QWidget(parent), m_kind(kind), m_channels(channelsOf(kind))
{
    setObjectName(QStringLiteral("chartView_%1").arg(QLatin1String(traits(kind).fileStem)));
    m_visible = channelMask(kind);
    m_fixedMin = traits(kind).fixedMin;
    m_fixedMax = traits(kind).fixedMax;

    m_canvas = new PlotCanvas(this);
    m_canvas->setObjectName(QStringLiteral("chartArea"));
    m_canvas->setMinimumHeight(kMinimumChartHeight);
    // The legend (a chart of one axis has none) on the right, where it costs no height;
    // clicking an entry hides or shows that axis (dimmed while hidden).
    m_canvas->setLegendVisible(m_channels.size() > 1);
    for (Channel c : m_channels)
        m_lineOf[size_t(c)] = m_canvas->addLine(colour(c));
    connect(m_canvas, &PlotCanvas::legendClicked, this, [this](int line) {
        for (Channel c : m_channels)
            if (m_lineOf[size_t(c)] == line)
                setChannelVisible(c, !isChannelVisible(c));
    });
    m_canvas->installEventFilter(this);
    m_decimator.setExtremaOnly(true);

    // The note over the plot area: why the chart stays empty, and what would fill it.
    m_note = new QFrame(m_canvas);
    m_note->setObjectName(QStringLiteral("chartNote"));
    m_note->setFrameShape(QFrame::StyledPanel);
    m_note->setAutoFillBackground(true);
    auto *noteLayout = new QVBoxLayout(m_note);
    noteLayout->setContentsMargins(10, 8, 10, 8);
    m_noteLabel = new QLabel(m_note);
    m_noteLabel->setObjectName(QStringLiteral("chartNoteText"));
    m_noteLabel->setWordWrap(true);
    m_noteLabel->setAlignment(Qt::AlignCenter);
    noteLayout->addWidget(m_noteLabel);
    m_noteButton = new QPushButton(m_note);
    m_noteButton->setObjectName(QStringLiteral("chartNoteButton"));
    noteLayout->addWidget(m_noteButton, 0, Qt::AlignHCenter);
    connect(m_noteButton, &QPushButton::clicked, this, [this] {
        m_noteButton->setEnabled(false); // until the panel offers it again
        if (m_noteAction)
            m_noteAction();
    });
    connect(m_canvas, &PlotCanvas::plotAreaChanged, this, [this](const QRectF &) { placeNote(); });
    m_note->hide();

    // The context menu: the vertical range and saving this chart.
    m_menu = new QMenu(this);
    m_menu->setObjectName(QStringLiteral("chartMenu"));
    m_autoScaleAction = m_menu->addAction(QString());
    m_autoScaleAction->setObjectName(QStringLiteral("autoScaleAction"));
    m_autoScaleAction->setCheckable(true);
    m_autoScaleAction->setChecked(m_autoScale);
    connect(m_autoScaleAction, &QAction::toggled, this, &ChartView::setAutoScale);
    auto *range = new QWidget;
    auto *rangeRow = new QHBoxLayout(range);
    rangeRow->setContentsMargins(24, 2, 8, 2);
    m_rangeLabel = new QLabel(range);
    rangeRow->addWidget(m_rangeLabel);
    m_minSpin = new QDoubleSpinBox(range);
    m_maxSpin = new QDoubleSpinBox(range);
    for (QDoubleSpinBox *spin : {m_minSpin, m_maxSpin}) {
        spin->setRange(-1e7, 1e7);
        spin->setDecimals(traits(kind).spinDecimals);
        spin->setKeyboardTracking(false);
        rangeRow->addWidget(spin);
    }
    m_minSpin->setObjectName(QStringLiteral("minSpin"));
    m_maxSpin->setObjectName(QStringLiteral("maxSpin"));
    m_minSpin->setValue(m_fixedMin);
    m_maxSpin->setValue(m_fixedMax);
    connect(m_minSpin, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { setFixedRange(v, m_maxSpin->value()); });
    connect(m_maxSpin, &QDoubleSpinBox::valueChanged, this,
            [this](double v) { setFixedRange(m_minSpin->value(), v); });
    auto *rangeAction = new QWidgetAction(m_menu);
    rangeAction->setDefaultWidget(range);
    m_menu->addAction(rangeAction);
    m_menu->addSeparator();
    m_saveAction = m_menu->addAction(QString());
    m_saveAction->setObjectName(QStringLiteral("savePngAction"));
    connect(m_saveAction, &QAction::triggered, this, &ChartView::saveAsPngInteractive);
    m_canvas->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_canvas, &QWidget::customContextMenuRequested, this,
            [this](const QPoint &pos) { m_menu->popup(m_canvas->mapToGlobal(pos)); });

    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("crosshairReadout"));
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout->setMinimumWidth(1);
    m_readout->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_readout->setMinimumHeight(m_readout->fontMetrics().height()); // no jumps when it fills
    m_readout->hide(); // until the panel's cursor is switched on

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addWidget(m_canvas, 1);
    layout->addWidget(m_readout);

    updateScaleWidgets();
    retranslateUi();
    applyXAxis(liveWindow());
    applyYAxis(m_fixedMin, m_fixedMax);
}

ChartView::~ChartView() = default;

void ChartView::retranslateUi()
{
    m_canvas->setTitle(title(m_kind));
    const QString u = shownUnit();
    m_canvas->setAxisTitles(timeAxisTitle(m_timeAxis),
                            u.isEmpty() ? quantity(m_kind) : tr("%1 (%2)", "quantity (unit)").arg(quantity(m_kind), u));
    for (Channel c : m_channels)
        m_canvas->setLineName(m_lineOf[size_t(c)], axisName(c));
    m_canvas->setToolTip(m_channels.size() > 1
                                ? tr("Click an axis in the legend to hide or show it; right-click for the vertical "
                                     "range and to save this chart")
                                : tr("Right-click for the vertical range and to save this chart"));
    m_autoScaleAction->setText(tr("Auto scale"));
    m_autoScaleAction->setToolTip(tr("Fit the vertical axis to the data shown; off: use the fixed range"));
    m_rangeLabel->setText(u.isEmpty() ? tr("Fixed range:") : tr("Fixed range (%1):").arg(u));
    if (u.isEmpty()) {
        m_minSpin->setToolTip(tr("Lower end of the vertical axis (no unit)"));
        m_maxSpin->setToolTip(tr("Upper end of the vertical axis (no unit)"));
    } else {
        m_minSpin->setToolTip(tr("Lower end of the vertical axis, in %1").arg(u));
        m_maxSpin->setToolTip(tr("Upper end of the vertical axis, in %1").arg(u));
    }
    m_saveAction->setText(tr("Save as PNG…"));
    m_saveAction->setToolTip(tr("Save this chart as a PNG image"));
    if (m_crosshairOn)
        m_readout->setText(readoutAt(m_crosshairX));
}

void ChartView::updateScaleWidgets()
{
    m_minSpin->setEnabled(!m_autoScale);
    m_maxSpin->setEnabled(!m_autoScale);
    m_rangeLabel->setEnabled(!m_autoScale);
}

void ChartView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ChartView::showEvent(QShowEvent *event)
{
    markDirty();
    QWidget::showEvent(event);
}

void ChartView::resizeEvent(QResizeEvent *event)
{
    markDirty(); // another width, other columns
    QWidget::resizeEvent(event);
}

// ---------------------------------------------------------------- settings

void ChartView::setHistory(const plot::ChannelHistory *history)
{
    m_history = history;
    m_paused = false;
    m_haveYRange = false;
    markDirty();
}

void ChartView::setTimeAxis(TimeAxis axis)
{
    if (axis == m_timeAxis)
        return;
    m_timeAxis = axis;
    m_canvas->setAxisTitles(timeAxisTitle(axis), m_canvas->yTitle());
    if (m_paused) // the frozen range is on the other axis
        setPaused(false);
    hideCrosshair();
    markDirty();
}

void ChartView::setWindowSeconds(double seconds)
{
    if (!ChartSettings::isWindowChoice(seconds) || seconds == m_window)
        return;
    m_window = seconds;
    if (m_paused) // keep the right edge where it was
        m_frozen.t0 = m_frozen.t1 - m_window;
    m_haveYRange = false;
    markDirty();
    Q_EMIT settingsChanged();
}

void ChartView::setChannelVisible(Channel channel, bool visible)
{
    if (!(channelMask(m_kind) & plot::channelBit(channel)) || visible == isChannelVisible(channel))
        return;
    if (visible)
        m_visible |= plot::channelBit(channel);
    else
        m_visible &= ~plot::channelBit(channel);
    m_canvas->setLineVisible(m_lineOf[size_t(channel)], visible); // a hidden line drops its points
    m_haveYRange = false;
    markDirty();
    if (m_crosshairOn)
        m_readout->setText(readoutAt(m_crosshairX));
    Q_EMIT settingsChanged();
}

bool ChartView::isChannelVisible(Channel channel) const
{
    return (m_visible & plot::channelBit(channel)) != 0;
}

void ChartView::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    if (paused)
        m_frozen = m_drawn.valid ? m_drawn : liveWindow();
    markDirty();
}

void ChartView::setAutoScale(bool on)
{
    if (on == m_autoScale)
        return;
    m_autoScale = on;
    {
        const QSignalBlocker blocker(m_autoScaleAction);
        m_autoScaleAction->setChecked(on);
    }
    m_haveYRange = false;
    updateScaleWidgets();
    markDirty();
}

void ChartView::setFixedRange(double min, double max)
{
    if (!(min < max) || (min == m_fixedMin && max == m_fixedMax))
        return;
    m_fixedMin = min;
    m_fixedMax = max;
    const QSignalBlocker b1(m_minSpin), b2(m_maxSpin);
    m_minSpin->setValue(min);
    m_maxSpin->setValue(max);
    markDirty();
}

// ---------------------------------------------------------------- drawing

int ChartView::plotWidthPx() const
{
    const int w = int(m_canvas->plotArea().width());
    if (w >= 1)
        return w;
    return std::max(1, m_canvas->width() - 80); // before the first layout
}

ChartView::Window ChartView::liveWindow() const
{
    Window w;
    w.valid = true;
    if (!m_history || m_history->empty()) {
        w.t0 = 0.0;
        w.t1 = m_window;
        return w;
    }
    w.t1 = m_history->newestTime(m_timeAxis);
    w.t0 = w.t1 - m_window;
    w.offset = m_timeAxis == TimeAxis::Device ? m_history->deviceTimeOffset() : 0.0;
    return w;
}

void ChartView::applyXAxis(const Window &w)
{
    const double step = plot::AxisScaling::timeTickInterval(w.t1 - w.t0);
    m_canvas->setXRange(w.t0 - w.offset, w.t1 - w.offset, step, plot::AxisScaling::decimalsFor(step));
}

void ChartView::applyYAxis(double min, double max)
{
    const double step = plot::AxisScaling::niceStep(max - min, 5);
    m_canvas->setYRange(min, max, step, plot::AxisScaling::decimalsFor(step));
}

void ChartView::setUnits(const model::DisplayUnits &units)
{
    if (units == m_units)
        return;
    const double before = unitFactor();
    m_units = units;
    // A fixed range keeps showing the same physical span.
    const double scale = unitFactor() / before;
    if (scale != 1.0)
        setFixedRange(m_fixedMin * scale, m_fixedMax * scale);
    m_haveYRange = false;
    retranslateUi();
    markDirty();
}

double ChartView::unitFactor() const
{
    switch (m_kind) {
    case ChartKind::Accelerometer: return m_units.accelFactor();
    case ChartKind::Gyroscope: return m_units.rateFactor();
    default: return 1.0;
    }
}

QString ChartView::shownUnit() const
{
    if (m_kind == ChartKind::Accelerometer && m_units.accel == model::AccelUnit::MetresPerSecondSquared)
        return tr("m/s²");
    if (m_kind == ChartKind::Gyroscope && m_units.rate == model::RateUnit::RadiansPerSecond)
        return tr("rad/s");
    return unit(m_kind);
}

const QList<QPointF> &ChartView::linePoints(Channel channel) const
{
    return m_canvas->points(m_lineOf[size_t(channel)]);
}

bool ChartView::refresh()
{
    if (!m_history || !isVisible() || visibleRegion().isEmpty())
        return false;
    const uint64_t revision = m_history->revision();
    const bool newData = revision != m_drawnRevision;
    if (!m_dirty && (!newData || m_paused))
        return false;
    const Window w = m_paused ? m_frozen : liveWindow();
    const int width = plotWidthPx();
    // New data, but the window moved by less than a pixel column: nothing to see yet. (A few
    // pixels more or less of plot area, as axis labels change width, need no redraw either:
    // the chart places the points; a real resize marks the chart dirty.)
    if (!m_dirty && m_drawn.valid && w.offset == m_drawn.offset && m_history->generation() == m_drawnGeneration) {
        const double column = (w.t1 - w.t0) / width;
        if (std::abs(w.t1 - m_drawn.t1) < column)
            return false;
    }

    // The legend lists the quantities the device sends (every one while none has come yet): an
    // HEC495's magnetic roll has no entry beside a module's Euler angles.
    const bool anyCarried = std::any_of(m_channels.begin(), m_channels.end(),
                                        [this](Channel c) { return m_history->columnData(c) != nullptr; });
    for (Channel c : m_channels)
        m_canvas->setLineListed(m_lineOf[size_t(c)], !anyCarried || m_history->columnData(c) != nullptr);

    double lo = 0.0, hi = 0.0;
    bool any = false;
    for (Channel c : m_channels) {
        if (!isChannelVisible(c))
            continue;
        // Decimated straight into the canvas's own list: no copy, no allocation once it has grown.
        QList<QPointF> &points = m_canvas->pointsToFill(m_lineOf[size_t(c)]);
        auto r = m_decimator.decimate(*m_history, c, m_timeAxis, w.t0, w.t1, width, points, w.offset);
        if (const double factor = unitFactor(); factor != 1.0) {
            for (QPointF &p : points)
                p.ry() *= factor; // a break marker stays NaN
            r.yMin *= factor;
            r.yMax *= factor;
        }
        if (r.rows > 0) {
            lo = any ? std::min(lo, r.yMin) : r.yMin;
            hi = any ? std::max(hi, r.yMax) : r.yMax;
            any = true;
        }
    }
    applyXAxis(w);
    if (m_autoScale) {
        if (any) {
            m_yRange = plot::AxisScaling::autoRange(m_yRange, m_haveYRange, lo, hi,
                                                    traits(m_kind).minSpan * unitFactor());
            m_haveYRange = true;
        }
        if (m_haveYRange)
            applyYAxis(m_yRange.min, m_yRange.max);
    } else {
        applyYAxis(m_fixedMin, m_fixedMax);
    }

    m_drawn = w;
    m_drawnRevision = revision;
    m_drawnGeneration = m_history->generation();
    m_drawnWidth = width;
    m_dirty = false;
    ++m_redraws;
    if (m_crosshairOn)
        m_readout->setText(readoutAt(m_crosshairX));
    return true;
}

// ---------------------------------------------------------------- crosshair

void ChartView::setNote(const QString &text, const QString &actionText, const std::function<void()> &action,
                        bool actionEnabled)
{
    m_noteLabel->setText(text);
    m_noteAction = action;
    m_noteButton->setText(actionText);
    m_noteButton->setVisible(!actionText.isEmpty());
    m_noteButton->setEnabled(actionEnabled);
    m_note->show();
    placeNote();
}

void ChartView::clearNote()
{
    m_note->hide();
    m_noteAction = {};
}

bool ChartView::hasNote() const
{
    return !m_note->isHidden();
}

QString ChartView::noteText() const
{
    return hasNote() ? m_noteLabel->text() : QString();
}

void ChartView::placeNote()
{
    if (m_note->isHidden())
        return;
    // Centred on the plot area, as wide as it allows (at most 460 px), never wider than the canvas.
    const QRect area = m_canvas->plotArea().toAlignedRect().isValid() ? m_canvas->plotArea().toAlignedRect()
                                                                       : m_canvas->rect();
    const int width = std::max(1, std::min({460, area.width() - 16, m_canvas->width()}));
    m_note->setFixedWidth(width);
    const int height = std::min(m_note->heightForWidth(width) > 0 ? m_note->heightForWidth(width)
                                                                 : m_note->sizeHint().height(),
                                m_canvas->height());
    m_note->setFixedHeight(height);
    m_note->move(area.center().x() - width / 2, std::max(0, area.center().y() - height / 2));
    m_note->raise();
}

bool ChartView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_canvas && event->type() == QEvent::Resize)
        placeNote();
    if (watched == m_canvas && m_cursorEnabled) {
        if (event->type() == QEvent::MouseMove) {
            const QPointF pos = static_cast<QMouseEvent *>(event)->position();
            if (m_canvas->plotArea().contains(pos)) {
                showCrosshairAt(m_canvas->toValue(pos).x());
                Q_EMIT crosshairMoved(m_crosshairX);
            } else {
                hideCrosshair();
                Q_EMIT crosshairLeft();
            }
        } else if (event->type() == QEvent::Leave) {
            hideCrosshair();
            Q_EMIT crosshairLeft();
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ChartView::setCursorEnabled(bool on)
{
    m_cursorEnabled = on;
    m_readout->setVisible(on);
    if (!on)
        hideCrosshair();
}

void ChartView::showCrosshairAt(double x)
{
    m_crosshairX = x;
    m_crosshairOn = true;
    m_canvas->setCrosshair(x);
    m_readout->setText(readoutAt(x));
}

void ChartView::hideCrosshair()
{
    if (!m_crosshairOn)
        return;
    m_crosshairOn = false;
    m_canvas->setCrosshair(std::nullopt);
    m_readout->clear();
}

QString ChartView::crosshairText() const
{
    return m_crosshairOn ? m_readout->text() : QString();
}

QString ChartView::readoutAt(double x) const
{
    QStringList parts;
    parts << tr("t = %1 s").arg(x, 0, 'f', 3);
    const double t = x + (m_drawn.valid ? m_drawn.offset : 0.0);
    const QString u = shownUnit();
    const double factor = unitFactor();
    // Farther than this from the nearest sample, the value is not known (a gap).
    double tolerance = std::numeric_limits<double>::infinity();
    if (m_history && m_history->samplePeriod() > 0.0) {
        const double column = m_drawn.valid ? (m_drawn.t1 - m_drawn.t0) / std::max(1, m_drawnWidth) : 0.0;
        tolerance = std::max(2.0 * column, plot::ChannelHistory::kGapPeriods * m_history->samplePeriod());
    }
    for (Channel c : m_channels) {
        if (!isChannelVisible(c))
            continue;
        QString value = QStringLiteral("\u2014");
        if (m_history) {
            const long long row = m_history->nearestRow(m_timeAxis, t, c);
            if (row >= 0 && std::abs(m_history->time(m_timeAxis, size_t(row)) - t) <= tolerance)
                value = QString::number(double(m_history->value(c, size_t(row))) * factor, 'f',
                                        valueDecimals(m_kind) + (factor < 0.1 ? 2 : 0));
        }
        parts << tr("%1 %2 %3", "crosshair read-out: axis, value, unit").arg(axisName(c), value, u).trimmed();
    }
    return parts.join(QStringLiteral("   "));
}

// ---------------------------------------------------------------- PNG

bool ChartView::savePng(const QString &path, QString *error) const
{
    return saveWidgetPng(m_canvas, path, error);
}

void ChartView::saveAsPngInteractive()
{
    savePngInteractive(this, QLatin1String(traits(m_kind).fileStem),
                       [this](const QString &path, QString *error) { return savePng(path, error); });
}

void ChartView::savePngInteractive(QWidget *parent, const QString &fileStem,
                                   const std::function<bool(const QString &, QString *)> &save)
{
    const QString suggested = QStringLiteral("imudesk-%1-%2.png")
                                  .arg(fileStem, QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    QString path = QFileDialog::getSaveFileName(parent, tr("Save Chart as PNG"), suggested, tr("PNG images (*.png)"));
    if (path.isEmpty())
        return;
    if (!path.endsWith(QLatin1String(".png"), Qt::CaseInsensitive))
        path += QLatin1String(".png");
    QString error;
    if (!save(path, &error))
        QMessageBox::warning(parent, tr("Save Chart as PNG"), error);
}

} // namespace imudesk::ui
