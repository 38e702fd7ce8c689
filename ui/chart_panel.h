#pragma once
// The live charts of one device: accelerometer, gyroscope, magnetometer, Euler angles,
// quaternion, pressure and temperature, stacked in a scroll area under a time-axis
// choice. It owns the device's plot::ChannelHistory.
//
// The device workspace drives it on its view clock: appendSamples() with the samples
// that arrived since the last tick (cheap: columns only), then refresh() (≤ 60 Hz),
// which redraws only the charts that are on screen and have something new to show.
// Charts of quantities the device never sent (e.g. pressure on a module without a
// barometer) are hidden once data arrives.
#include "chart_settings.h"
#include "model/display_units.h"
#include "model/sample.h"
#include "plot/channel_history.h"

#include <QWidget>

#include <array>
#include <vector>

class QComboBox;
class QLabel;
class QScrollArea;

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

    ChartSettings settings() const;
    void setSettings(const ChartSettings &settings);

    ChartView *chart(ChartKind kind) const { return m_charts[size_t(kind)]; }
    QScrollArea *scrollArea() const { return m_scroll; }
    QComboBox *timeAxisCombo() const { return m_timeAxisCombo; }

Q_SIGNALS:
    // A chart's window or visible axes, or the time axis, changed: the owner may save settings().
    void settingsChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateChartVisibility();

    plot::ChannelHistory m_history;
    plot::TimeAxis m_timeAxis = plot::TimeAxis::Device;
    int m_refreshCount = 0;
    uint32_t m_shownPresence = ~0u;

    std::array<ChartView *, kChartKindCount> m_charts{};
    QLabel *m_timeAxisLabel = nullptr;
    QComboBox *m_timeAxisCombo = nullptr;
    QScrollArea *m_scroll = nullptr;
};

} // namespace imudesk::ui
