#pragma once
// One channel (e.g. yaw) of several devices on one chart, for side-by-side
// comparison. The sources are ChannelHistory objects owned elsewhere (each device's
// ChartPanel), labelled e.g. with the device's port. Device clocks differ, so the
// x axis is host arrival time: seconds since the earliest of the sources' first
// samples. Decimated like ChartView; refresh() on the view clock redraws only while
// visible and when a source has new data that moves the window by a pixel column.
#include "plot/axis_scaling.h"
#include "plot/channel_history.h"
#include "plot/minmax_decimator.h"

#include <QList>
#include <QPointF>
#include <QString>
#include <QWidget>

#include <utility>
#include <vector>

class QChart;
class QChartView;
class QComboBox;
class QLabel;
class QLineSeries;
class QPushButton;
class QToolButton;
class QValueAxis;

namespace imudesk::ui {

class ComparisonChart : public QWidget {
    Q_OBJECT
public:
    using Source = std::pair<QString, const plot::ChannelHistory *>;
    // The legend, the plot and the time axis with its labels (below this QChart elides them).
    static constexpr int kMinimumChartHeight = 240;

    explicit ComparisonChart(QWidget *parent = nullptr);
    ~ComparisonChart() override;

    // The histories must outlive this chart or be replaced first (setSources({})).
    void setSources(std::vector<Source> sources);
    const std::vector<Source> &sources() const { return m_sources; }

    void setChannel(plot::Channel channel);
    plot::Channel channel() const { return m_channel; }
    void setWindowSeconds(double seconds);
    double windowSeconds() const { return m_window; }
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }

    bool refresh();
    int redrawCount() const { return m_redraws; }
    bool savePng(const QString &path, QString *error = nullptr) const;

    // x of source i = its host time + sourceOffset(i) (valid after a redraw).
    double sourceOffset(int index) const;
    int plotWidthPx() const;
    int drawnWidthPx() const { return m_drawnWidth; }

    QChart *chart() const { return m_chart; }
    QChartView *chartView() const { return m_chartView; }
    QLineSeries *series(int index) const;
    QValueAxis *axisX() const { return m_axisX; }
    QValueAxis *axisY() const { return m_axisY; }
    QComboBox *channelCombo() const { return m_channelCombo; }

Q_SIGNALS:
    void channelChanged(plot::Channel channel);

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    struct Window {
        double t0 = 0.0;
        double t1 = 0.0;
        bool valid = false;
    };

    void retranslateUi();
    void updateAxisTitles();
    void updatePauseButton();
    void rebuildSeries();
    void computeOffsets();
    Window liveWindow() const;
    void saveAsPngInteractive();

    std::vector<Source> m_sources;
    std::vector<QLineSeries *> m_series;
    std::vector<double> m_offsets;        // host time -> x, per source
    std::vector<uint64_t> m_drawnRevisions;
    std::vector<QList<QPointF>> m_points;
    plot::MinMaxDecimator m_decimator;

    plot::Channel m_channel = plot::Channel::Yaw;
    double m_window = 10.0;
    bool m_paused = false;
    Window m_frozen;
    Window m_drawn;
    int m_drawnWidth = 0;
    bool m_dirty = true;
    int m_redraws = 0;
    plot::AxisScaling::Range m_yRange;
    bool m_haveYRange = false;

    QChart *m_chart = nullptr;
    QChartView *m_chartView = nullptr;
    QValueAxis *m_axisX = nullptr;
    QValueAxis *m_axisY = nullptr;
    QLabel *m_channelLabel = nullptr;
    QComboBox *m_channelCombo = nullptr;
    QLabel *m_windowLabel = nullptr;
    QComboBox *m_windowCombo = nullptr;
    QToolButton *m_pauseButton = nullptr;
    QPushButton *m_saveButton = nullptr;
};

} // namespace imudesk::ui
