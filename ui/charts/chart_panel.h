#pragma once
// The live charts of one device: accelerometer, gyroscope, magnetometer, Euler angles,
// quaternion, pressure and temperature. The charts the user chose (four by default) share
// the central area in a grid that fills it (two columns when there is room), under one
// toolbar for all of them: which charts, time window, pause/run, time axis, cursor (a
// crosshair that reads out every chart at the same time) and "Save all as PNG". It owns the
// device's plot::ChannelHistory.
//
// The device workspace drives it on its view clock: appendSamples() with the samples
// that arrived since the last tick (cheap: columns only), then refresh() (≤ 60 Hz),
// which redraws only the charts that are on screen and have something new to show.
// Charts of quantities the device never sent (e.g. pressure on a module without a
// barometer) are hidden once data arrives.
//
// Folder ui/charts/: the live charts (ChartPanel, ChartView, ChartSettings, PlotCanvas), the
// multi-device ComparisonChart, the AnalysisWindow for recordings and the BandwidthCalculator.
// It mirrors core/plot: ChartPanel holds the device's plot::ChannelHistory, and ChartView
// decimates it with plot::MinMaxDecimator and scales it with plot::AxisScaling before
// PlotCanvas paints it. ComparisonChart and AnalysisWindow (core/record's file analysis and
// Allan deviation) draw with Qt Charts; the BandwidthCalculator shows core/settings'
// BandwidthCalculator. No item models: the device workspace feeds the charts on its view clock.
#include "charts/chart_settings.h"
#include "model/display_units.h"
#include "model/sample.h"
#include "plot/channel_history.h"

#include <QWidget>

#include <array>
#include <functional>
#include <vector>

class QAction;
class QComboBox;
class QGridLayout;
class QLabel;
class QToolBar;
class QToolButton;

namespace imudesk::ui {

class ChartView;

class ChartPanel : public QWidget {
    Q_OBJECT
public:
    explicit ChartPanel(QWidget *parent = nullptr);
    ~ChartPanel() override;

    void appendSamples(const std::vector<model::Sample> &batch);
    // Forgets the recorded data (e.g. on reconnect).
    void clear();
    // Redraws the visible charts that need it.
    void refresh();
    // Charts redrawn so far.
    int refreshCount() const { return m_refreshCount; }

    const plot::ChannelHistory &history() const { return m_history; }

    // Device clock or host arrival time, for all charts.
    void setTimeAxis(plot::TimeAxis axis);
    // Units for the accelerometer and gyroscope charts.
    void setUnits(const model::DisplayUnits &units);
    // How much the charts keep (1 to 10 minutes at up to 1 kHz).
    void setHistoryMinutes(int minutes);
    plot::TimeAxis timeAxis() const { return m_timeAxis; }
    // The time window of every chart (one of ChartSettings::kWindowChoices).
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_window; }
    // Pauses or resumes every chart (the history keeps recording).
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    // The crosshair and its read-out line under every chart.
    void setCursorEnabled(bool on);
    bool isCursorEnabled() const { return m_cursorEnabled; }
    // Whether the user wants a chart (it shows once its quantity has data, or before any).
    void setChartChosen(ChartKind kind, bool chosen);
    bool isChartChosen(ChartKind kind) const { return !((m_hiddenCharts >> int(kind)) & 1u); }
    // Columns of the grid as laid out now.
    int gridColumns() const { return m_columns; }

    ChartSettings settings() const;
    void setSettings(const ChartSettings &settings);

    static constexpr int kSavedMessageMs = 10000; // how long the status bar says where the PNG went
    // A chart whose quantity has not arrived for this long (host s) while other data does says
    // so on the chart: the device's output carries none at its current setting.
    static constexpr double kMissingAfterS = 2.0;
    // After the output switch was clicked, its button waits this long (host s) for the data.
    static constexpr double kSwitchWaitS = 5.0;

    // A device whose output can be set to carry what some charts miss (an HEC495 that streams
    // its angles only): those charts (bit per ChartKind) show even before their quantity
    // arrives, and their note offers a button, label(), that calls action().
    void offerOutputSwitch(uint32_t charts, std::function<QString()> label, std::function<void()> action);
    // What a chart's note says when its quantity does not arrive.
    static QString missingText(ChartKind kind);

    // All charts shown, as one PNG.
    bool saveAllPng(const QString &path, QString *error = nullptr) const;
    // What Save all as PNG does once its file dialog has a name: saves, then says where (the
    // window's status bar, pngSaved()).
    bool saveAllPngAndSay(const QString &path, QString *error = nullptr);

    ChartView *chart(ChartKind kind) const { return m_charts[size_t(kind)]; }
    QWidget *chartArea() const { return m_area; }
    QToolBar *toolBar() const { return m_toolBar; }
    QComboBox *timeAxisCombo() const { return m_timeAxisCombo; }
    QComboBox *windowCombo() const { return m_windowCombo; }
    QAction *pauseAction() const { return m_pauseAction; }
    QAction *cursorAction() const { return m_cursorAction; }
    QAction *chartAction(ChartKind kind) const { return m_chartActions[size_t(kind)]; }

Q_SIGNALS:
    // The window, the charts or visible axes, or the time axis changed: the owner may save settings().
    void settingsChanged();
    // "Save all as PNG…" wrote `path`; `message` (also in the window's status bar) says where.
    void pngSaved(const QString &path, const QString &message);

protected:
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void retranslateUi();
    void updateChartVisibility(bool force = false);
    void layoutCharts();
    void tellSaved(const QString &path);
    void updateNotes();

    plot::ChannelHistory m_history;
    plot::TimeAxis m_timeAxis = plot::TimeAxis::Device;
    double m_window = ChartSettings::kDefaultWindowSeconds;
    bool m_paused = false;
    bool m_cursorEnabled = false;
    uint32_t m_hiddenCharts = ChartSettings::kDefaultHiddenCharts;
    int m_refreshCount = 0;
    uint32_t m_shownPresence = ~0u;
    uint32_t m_shownCharts = 0; // bit per ChartKind, as laid out
    int m_columns = 0;
    uint32_t m_offerCharts = 0; // bit per ChartKind
    std::function<QString()> m_offerLabel;
    std::function<void()> m_offerAction;
    double m_switchClickedAt = -1.0; // host time (s) of the newest row when the switch was clicked

    std::array<ChartView *, kChartKindCount> m_charts{};
    std::array<QAction *, kChartKindCount> m_chartActions{};
    QToolBar *m_toolBar = nullptr;
    QToolButton *m_chartsButton = nullptr;
    QLabel *m_windowLabel = nullptr;
    QComboBox *m_windowCombo = nullptr;
    QAction *m_pauseAction = nullptr;
    QLabel *m_timeAxisLabel = nullptr;
    QComboBox *m_timeAxisCombo = nullptr;
    QAction *m_cursorAction = nullptr;
    QAction *m_saveAllAction = nullptr;
    QWidget *m_area = nullptr;
    QGridLayout *m_grid = nullptr;
};

} // namespace imudesk::ui
