#pragma once
// The Trend tab (issue 38): one measurement of the plan chosen in the filter row over time:
// every module's value (passes green, failures red; ERROR and ABORTED modules are left out, as
// ResultsStore::series does), the limits and the marginal band as lines (they follow the plan's
// changes), and a line with n, mean, σ and Cpk against the latest limits.
#include "core/results/results_store.h"

#include <QWidget>

#include <vector>

QT_BEGIN_NAMESPACE
class QComboBox;
class QLabel;
class QChart;
class QChartView;
class QDateTimeAxis;
class QLineSeries;
class QScatterSeries;
class QValueAxis;
QT_END_NAMESPACE

namespace imudesk::ui {

class ElidedLabel;

class TrendView : public QWidget {
    Q_OBJECT

public:
    explicit TrendView(QWidget *parent = nullptr);

    // The plan's measurements; the one chosen before stays chosen when it is still there.
    void setMeasurements(const QStringList &names);
    QString measurement() const;
    void showSeries(const QString &measurement, std::vector<results::ResultsStore::Point> points,
                    const results::ResultsStore::Capability &capability);
    // No chart, and why (no plan chosen, no measurement, being read).
    void showMessage(const QString &text);

    QComboBox *measurementCombo() const { return m_measurement; }
    QChartView *chartView() const { return m_view; }
    int pointCount() const;
    int failureCount() const;
    QString statsText() const;
    // "1.23", or "–" when Cpk is not defined (no limit, σ = 0).
    static QString cpkText(double cpk);

Q_SIGNALS:
    void measurementChosen(const QString &name);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateStats();
    void fitAxes();

    std::vector<results::ResultsStore::Point> m_points;
    results::ResultsStore::Capability m_capability;
    bool m_haveSeries = false;
    QString m_message;

    QLabel *m_measurementTitle = nullptr;
    QComboBox *m_measurement = nullptr;
    QChart *m_chart = nullptr;
    QChartView *m_view = nullptr;
    QDateTimeAxis *m_x = nullptr;
    QValueAxis *m_y = nullptr;
    QScatterSeries *m_pass = nullptr;
    QScatterSeries *m_fail = nullptr;
    QLineSeries *m_low = nullptr, *m_high = nullptr, *m_marginalLow = nullptr, *m_marginalHigh = nullptr;
    ElidedLabel *m_stats = nullptr;
    QLabel *m_messageLabel = nullptr;
};

} // namespace imudesk::ui
