#pragma once
// The analysis of a recording (a capture or a vendor CSV): a table of per-channel
// statistics, a summary (output rate, jitter, frames lost, random walk, bias instability,
// recommended recording length), a histogram of frame intervals and the Allan deviation of
// the gyro and accelerometer axes on log-log axes. analyzeFile() runs as a
// jobs::BackgroundJob; closing the window cancels it. It opens at kDefaultSize (within 95 % of
// the screen) the first time, then at the size and split it was last closed with.
#include "jobs/background_job.h"
#include "record/sample_analyzer.h"

#include <QSize>
#include <QWidget>

class QChart;
class QSplitter;
class QLabel;
class QTableWidget;

namespace imudesk::ui {

class AnalysisWindow : public QWidget {
    Q_OBJECT
public:
    static constexpr QSize kDefaultSize{1100, 760};
    static constexpr const char *kGeometryKey = "analysisWindow/geometry";
    static constexpr const char *kSplitKey = "analysisWindow/tableBesideCharts"; // was analysisWindow/split: above them

    explicit AnalysisWindow(QWidget *parent = nullptr);
    ~AnalysisWindow() override;

    void analyzeFile(const QString &path, double tauMax = 1000.0);
    void setResult(const record::SampleAnalyzer::Result &result);

    QTableWidget *statsTable() const { return m_table; }
    QChart *histogramChart() const { return m_histogram; }
    QChart *allanChart() const { return m_allan; }
    QString summaryText() const;

Q_SIGNALS:
    void analysisFinished(bool ok, const QString &message);

protected:
    void closeEvent(QCloseEvent *event) override;

private:
    void placeSplit();
    void fillHistogram(const record::SampleAnalyzer::Result &r);
    void fillAllan(const record::SampleAnalyzer::Result &r);

    QTableWidget *m_table = nullptr;
    QSplitter *m_split = nullptr;
    bool m_splitKept = false; // as the user left it (restored or moved): not placed again
    QLabel *m_summary = nullptr;
    QChart *m_histogram = nullptr;
    QChart *m_allan = nullptr;
    jobs::BackgroundJob m_job; // last: cancelled and joined before the rest goes
};

} // namespace imudesk::ui
