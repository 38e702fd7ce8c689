#pragma once
// One live chart of a ChartPanel (e.g. the accelerometer): a PlotCanvas with one line
// per axis in a fixed colour. Its legend entries switch the axes on and off;
// its context menu holds auto scale or a fixed range and "Save as PNG…"; the time window,
// pause and the crosshair are the panel's, shared by all charts. Below the plot, while the
// panel's cursor is on, the crosshair read-out.
//
// It draws from a plot::ChannelHistory it does not own. refresh() is called from
// outside on the view clock; it redraws only while the chart is on screen, and only
// when the settings changed or new data moved the window by at least one pixel
// column. A redraw decimates each visible axis to at most 4 points per pixel column
// (plot::MinMaxDecimator) and hands them to the canvas; a device-clock gap or restart
// shows as a break in the line.
//
// X is seconds: on the device axis the device's own clock (system_time) of the newest
// segment; on the host axis the time since the history's first sample.
#include "charts/chart_settings.h"
#include "model/display_units.h"
#include "plot/axis_scaling.h"
#include "plot/channel_history.h"
#include "plot/minmax_decimator.h"

#include <QColor>
#include <QList>
#include <QPointF>
#include <QWidget>

#include <array>
#include <functional>
#include <vector>

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QMenu;
class QFrame;
class QPushButton;

namespace imudesk::ui {

class PlotCanvas;

class ChartView : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMinimumChartHeight = 150;

    explicit ChartView(ChartKind kind, QWidget *parent = nullptr);
    ~ChartView() override;

    // --- What a kind of chart shows (shared with ComparisonChart) ---
    static std::vector<plot::Channel> channelsOf(ChartKind kind);
    static uint32_t channelMask(ChartKind kind);
    static ChartKind kindOf(plot::Channel channel);
    static QString title(ChartKind kind);       // "Accelerometer"
    static QString quantity(ChartKind kind);    // "Acceleration"
    static QString unit(ChartKind kind);        // "G"; empty for the quaternion
    static QString axisName(plot::Channel channel);    // "X", "Roll", "Pressure"
    static QString channelName(plot::Channel channel); // "Acceleration X", "Yaw"
    static QColor colour(plot::Channel channel);
    // Asks where to save a chart (suggesting imudesk-<stem>-<time>.png), then calls save(path, &error)
    // and reports a failure in a message box. Shared by ChartView and ComparisonChart.
    static void savePngInteractive(QWidget *parent, const QString &fileStem,
                                   const std::function<bool(const QString &, QString *)> &save);
    static int valueDecimals(ChartKind kind);
    static QString timeAxisTitle(plot::TimeAxis axis);
    // "2 s" ... "10 min" for ChartSettings::kWindowChoices.
    static QString windowText(double seconds);
    static void fillWindowCombo(QComboBox *combo, double selected);
    // The "Window:" label (its buddy set) and its combo of time spans, filled with `selected`
    // current; `chosen` gets the seconds the user picks. The chart panel and the comparison
    // chart share it.
    static QComboBox *makeWindowChooser(QWidget *parent, double selected, QLabel *&label,
                                        const std::function<void(double)> &chosen);
    // Grabs `widget` and writes it as PNG; false with a message when the file cannot be written.
    static bool saveWidgetPng(QWidget *widget, const QString &path, QString *error);

    ChartKind kind() const { return m_kind; }

    void setHistory(const plot::ChannelHistory *history);
    const plot::ChannelHistory *history() const { return m_history; }

    void setTimeAxis(plot::TimeAxis axis);
    plot::TimeAxis timeAxis() const { return m_timeAxis; }
    // One of ChartSettings::kWindowChoices (others are ignored).
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_window; }
    void setChannelVisible(plot::Channel channel, bool visible);
    bool isChannelVisible(plot::Channel channel) const;
    // A paused chart keeps its x range (the history keeps recording).
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    void setAutoScale(bool on);
    bool autoScale() const { return m_autoScale; }
    // Used when autoscale is off; ignored unless min < max.
    void setFixedRange(double min, double max);
    double fixedMin() const { return m_fixedMin; }
    double fixedMax() const { return m_fixedMax; }

    // Units for the accelerometer and gyroscope charts (the history keeps G and deg/s).
    void setUnits(const model::DisplayUnits &units);
    const model::DisplayUnits &units() const { return m_units; }
    // The unit this chart shows its values in, and the factor from the history's unit.
    QString shownUnit() const;
    double unitFactor() const;

    // Redraws if on screen and something changed; true if it redrew.
    bool refresh();
    int redrawCount() const { return m_redraws; }

    // Writes the chart as shown to `path` (PNG).
    bool savePng(const QString &path, QString *error = nullptr) const;

    // Crosshair at x (s, as shown on the x axis): a vertical line and the values of the
    // visible axes at that time. While the cursor is enabled the mouse drives it over the
    // plot area (crosshairMoved/crosshairLeft let the panel move the other charts' too) and
    // the read-out line is shown below the plot.
    void setCursorEnabled(bool on);
    bool isCursorEnabled() const { return m_cursorEnabled; }
    void showCrosshairAt(double x);
    void hideCrosshair();
    bool isCrosshairVisible() const { return m_crosshairOn; }
    QString crosshairText() const;
    // The read-out for time x, whether or not the crosshair is shown.
    QString readoutAt(double x) const;

    // The value shown at x = 0 is this far along the history's time axis.
    double displayOffset() const { return m_drawn.offset; }
    // Width of the plot area in pixels (what the decimator is given), and the width the
    // last redraw used.
    int plotWidthPx() const;
    int drawnWidthPx() const { return m_drawnWidth; }

    // A note over the plot area (ChartPanel's: the device's output carries no data for this
    // chart at its current setting), with a button when actionText is given; clicking it calls
    // `action` and disables the button until the note is set again with enabled true.
    // clearNote() removes it.
    void setNote(const QString &text, const QString &actionText = {}, const std::function<void()> &action = {},
                 bool actionEnabled = true);
    void clearNote();
    bool hasNote() const;
    QString noteText() const;
    QPushButton *noteButton() const { return m_noteButton; }

    // The surface the chart is drawn on: ranges, titles, plot area, legend entries.
    PlotCanvas *canvas() const { return m_canvas; }
    // The decimated points drawn for an axis at the last redraw (empty while hidden).
    const QList<QPointF> &linePoints(plot::Channel channel) const;
    // The context menu's pieces.
    QMenu *contextMenu() const { return m_menu; }
    QAction *autoScaleAction() const { return m_autoScaleAction; }
    QDoubleSpinBox *minSpin() const { return m_minSpin; }
    QDoubleSpinBox *maxSpin() const { return m_maxSpin; }
    QLabel *readoutLabel() const { return m_readout; }

Q_SIGNALS:
    // The window or the visible axes changed.
    void settingsChanged();
    // The mouse put the crosshair at x (as shown on the x axis), or left the plot.
    void crosshairMoved(double x);
    void crosshairLeft();

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Window {
        double t0 = 0.0;
        double t1 = 0.0;
        double offset = 0.0;
        bool valid = false;
    };

    void retranslateUi();
    void updateScaleWidgets();
    void applyXAxis(const Window &w);
    void applyYAxis(double min, double max);
    Window liveWindow() const;
    void saveAsPngInteractive();
    void markDirty() { m_dirty = true; }
    void placeNote();

    const ChartKind m_kind;
    const std::vector<plot::Channel> m_channels;
    const plot::ChannelHistory *m_history = nullptr;
    plot::MinMaxDecimator m_decimator;

    plot::TimeAxis m_timeAxis = plot::TimeAxis::Device;
    double m_window = ChartSettings::kDefaultWindowSeconds;
    uint32_t m_visible = 0; // channelBit() of visible axes
    bool m_paused = false;
    Window m_frozen;
    bool m_autoScale = true;
    double m_fixedMin = -1.0;
    double m_fixedMax = 1.0;
    plot::AxisScaling::Range m_yRange;
    bool m_haveYRange = false;
    model::DisplayUnits m_units;

    // What was drawn last.
    Window m_drawn;
    uint64_t m_drawnRevision = ~uint64_t(0);
    uint64_t m_drawnGeneration = 0;
    int m_drawnWidth = 0;
    bool m_dirty = true;
    int m_redraws = 0;

    double m_crosshairX = 0.0;
    bool m_crosshairOn = false;
    bool m_cursorEnabled = false;

    PlotCanvas *m_canvas = nullptr;
    std::array<int, plot::kChannelCount> m_lineOf{};
    QMenu *m_menu = nullptr;
    QAction *m_autoScaleAction = nullptr;
    QAction *m_saveAction = nullptr;
    QLabel *m_rangeLabel = nullptr;
    QDoubleSpinBox *m_minSpin = nullptr;
    QDoubleSpinBox *m_maxSpin = nullptr;
    QLabel *m_readout = nullptr;
    QFrame *m_note = nullptr;
    QLabel *m_noteLabel = nullptr;
    QPushButton *m_noteButton = nullptr;
    std::function<void()> m_noteAction;
};

} // namespace imudesk::ui
