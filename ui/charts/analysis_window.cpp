#include "charts/analysis_window.h"

#include "plot/axis_scaling.h"
#include "record/file_analysis.h"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QBarSeries>
#include <QChart>
#include <QChartView>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QTableWidget>
#include <QThread>
#include <QToolTip>
#include <QCursor>
#include <QTimer>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <memory>

namespace imudesk::ui {

AnalysisWindow::AnalysisWindow(QWidget *parent) : QWidget(parent)
{
    setWindowTitle(tr("Analysis"));
    m_table = new QTableWidget(0, 6, this);
    m_table->setObjectName(QStringLiteral("stats"));
    m_table->setHorizontalHeaderLabels({tr("Channel"), tr("Unit"), tr("Mean"), tr("Std. dev."), tr("Min"), tr("Max")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    // Rows of a line of text: the fourteen channels in view.
    m_table->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    m_table->verticalHeader()->hide();
    m_summary = new QLabel(this);
    m_summary->setObjectName(QStringLiteral("summary"));
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_histogram = new QChart;
    m_histogram->setTitle(tr("Frame intervals (device clock)"));
    // One set of bars, named by the y axis: the legend's line is height the bars need.
    m_histogram->legend()->hide();
    m_allan = new QChart;
    m_allan->setTitle(tr("Allan deviation"));
    // The six curves' names in a column at the side: in a row above the plot they made the chart
    // at least as wide as the row, which the table beside it needs.
    m_allan->legend()->setAlignment(Qt::AlignRight);
    // The table beside the two charts, one above the other: under the table (as first built)
    // the charts had a quarter of a laptop's screen, and in zh_CN, whose rows are taller, their
    // axes' labels and titles were cut to "...".
    auto *charts = new QSplitter(Qt::Vertical, this);
    charts->addWidget(new QChartView(m_histogram, charts));
    charts->addWidget(new QChartView(m_allan, charts));
    // Half the height each, whatever their contents ask for.
    charts->setStretchFactor(0, 1);
    charts->setStretchFactor(1, 1);
    charts->setSizes({1, 1});
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(m_table);
    split->addWidget(charts);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_summary);
    layout->addWidget(split, 1);
    m_split = split;

    // Big enough to read the table and both charts at once, within the screen; the size and the
    // split a user last left it at are kept.
    QSettings settings;
    const QByteArray geometry = settings.value(QLatin1String(kGeometryKey)).toByteArray();
    if (geometry.isEmpty() || !restoreGeometry(geometry)) {
        const QSize room = screen() ? screen()->availableGeometry().size() : QSize(1366, 768);
        resize(kDefaultSize.boundedTo(room * 95 / 100));
    }
    if (const QByteArray state = settings.value(QLatin1String(kSplitKey)).toByteArray(); !state.isEmpty())
        m_splitKept = split->restoreState(state);
    connect(split, &QSplitter::splitterMoved, this, [this] { m_splitKept = true; }); // the user's from now on
}

void AnalysisWindow::placeSplit()
{
    // Each column as wide as its widest text (its header's too) and a cell's margins, the table at
    // most half the width, the charts the rest (until the user moves the split); the last column
    // takes what the table has left.
    const QFontMetrics fm(m_table->font());
    const QFontMetrics headerFm(m_table->horizontalHeader()->font());
    int table = 2 * m_table->frameWidth() + 2;
    for (int c = 0; c < m_table->columnCount(); ++c) {
        int widest = m_table->horizontalHeaderItem(c) ? headerFm.horizontalAdvance(m_table->horizontalHeaderItem(c)->text()) : 0;
        for (int row = 0; row < m_table->rowCount(); ++row)
            if (const QTableWidgetItem *item = m_table->item(row, c))
                widest = std::max(widest, fm.horizontalAdvance(item->text()));
        const int width = widest + 2 * fm.horizontalAdvance(QLatin1Char('M'));
        m_table->setColumnWidth(c, width);
        table += width;
    }
    const int total = m_split->width() > 0 ? m_split->width() : kDefaultSize.width();
    // At least that wide from now on (the charts shrink first when the window does), at most half.
    m_table->setMinimumWidth(std::min(table, total / 2));
    m_split->setSizes({std::min(table, total / 2), std::max(total - table, total / 2)});
}

void AnalysisWindow::closeEvent(QCloseEvent *event)
{
    QSettings settings;
    settings.setValue(QLatin1String(kGeometryKey), saveGeometry());
    settings.setValue(QLatin1String(kSplitKey), m_split->saveState());
    QWidget::closeEvent(event);
}

AnalysisWindow::~AnalysisWindow() = default; // m_job cancels and joins a running analysis

void AnalysisWindow::analyzeFile(const QString &path, double tauMax)
{
    if (m_job.isRunning())
        return;
    m_summary->setText(tr("Analysing %1…").arg(path));
    m_job.launch(QStringLiteral("imudesk-analysis"), [this, path, tauMax](const jobs::BackgroundJob::Context &job) {
        auto outcome = std::make_shared<record::FileAnalysis::Outcome>(
            record::FileAnalysis::run(path, {}, tauMax, [&job](double f) {
                job.setProgress(f);
                return !job.cancelled();
            }));
        jobs::BackgroundJob::Outcome done{outcome->ok, outcome->error, {}};
        // In the window's thread, after the worker has ended.
        done.apply = [this, outcome] {
            if (!outcome->ok) {
                m_summary->setText(outcome->error);
                Q_EMIT analysisFinished(false, outcome->error);
                return;
            }
            setResult(outcome->result);
            const QString warnings = outcome->warnings.join(QLatin1Char('\n'));
            if (!warnings.isEmpty())
                m_summary->setText(m_summary->text() + QLatin1Char('\n') + warnings);
            Q_EMIT analysisFinished(true, warnings);
        };
        return done;
    });
}

QString AnalysisWindow::summaryText() const
{
    return m_summary->text();
}

void AnalysisWindow::setResult(const record::SampleAnalyzer::Result &r)
{
    m_table->setRowCount(int(r.channels.size()));
    for (int i = 0; i < int(r.channels.size()); ++i) {
        const auto &c = r.channels[size_t(i)];
        const QStringList cells = {QString::fromStdString(c.name), QString::fromStdString(c.unit),
                                   QString::number(c.mean, 'g', 7), QString::number(c.std, 'g', 5),
                                   QString::number(c.min, 'g', 7), QString::number(c.max, 'g', 7)};
        for (int col = 0; col < cells.size(); ++col)
            m_table->setItem(i, col, new QTableWidgetItem(cells.at(col)));
    }
    QStringList lines;
    lines << tr("%1: %2 frames over %3 s, output rate %4 Hz, interval %5 ± %6 ms, frames lost %7")
                 .arg(QString::fromStdString(r.source))
                 .arg(r.frames)
                 .arg(r.durationS, 0, 'f', r.durationS < 10 ? 2 : 1)
                 .arg(r.rateHz, 0, 'f', 2)
                 .arg(r.intervalMeanMs, 0, 'f', 3)
                 .arg(r.intervalStdMs, 0, 'f', 3)
                 .arg(r.framesLost);
    // A module that moved (not the sensor's noise) or a recording too short for τ = 1 s: no
    // Allan figures; the chart stays empty and says why.
    if (!r.allanJudged())
        lines << tr("Allan deviation: %1 (%2)").arg(r.allanReason(), r.allanDetail());
    // The units in the title, which has the chart's width (the y axis's title has only its height).
    m_allan->setTitle(r.allanJudged() ? tr("Allan deviation σ(τ): deg/s for gyro, G for acc")
                                      : tr("Allan deviation: %1").arg(r.allanReason()));
    for (const auto &a : r.axes) {
        const bool gyro = a.unit == "deg/s";
        QString line = QString::fromStdString(a.name) + QLatin1String(": ");
        if (a.summary.flat)
            line += tr("no noise to measure: its values never change (below the file's resolution, or a constant column)");
        if (a.summary.haveOneSecond)
            line += gyro ? tr("ARW %1 deg/√h").arg(a.summary.atOneSecond * 60.0, 0, 'g', 4)
                         : tr("VRW %1 m/s/√h").arg(a.summary.atOneSecond * model::kGravity * 60.0, 0, 'g', 4);
        if (a.summary.haveMinimum)
            line += QLatin1String(", ")
                + (gyro ? tr("bias instability %1 deg/h at τ = %2 s").arg(a.summary.biasInstability * 3600.0, 0, 'g', 4)
                        : tr("bias instability %1 mG at τ = %2 s").arg(a.summary.biasInstability * 1000.0, 0, 'g', 4))
                      .arg(a.summary.minimumTau, 0, 'g', 3);
        lines << line;
    }
    lines << tr("Recommended minimum recording length for τ up to %1 s: %2 h").arg(r.tauMax).arg(
        r.recommendedLengthS / 3600.0, 0, 'f', 1);
    m_summary->setText(lines.join(QLatin1Char('\n')));
    if (!m_splitKept) // once the summary's lines have taken their room
        QTimer::singleShot(0, this, [this] { placeSplit(); });
    fillHistogram(r);
    fillAllan(r);
}

void AnalysisWindow::fillHistogram(const record::SampleAnalyzer::Result &r)
{
    m_histogram->removeAllSeries();
    for (QAbstractAxis *axis : m_histogram->axes())
        m_histogram->removeAxis(axis);
    auto *set = new QBarSet(tr("frames"));
    QStringList labels;
    // The bars stand on a category axis without labels (twenty bins' edges side by side were cut
    // to "..." on a laptop's screen); a value axis in ms spans the same width below them, with a
    // few round ticks. A bar's tooltip and the CLI give its edges to the µs.
    for (const auto &b : r.intervals) {
        *set << double(b.count);
        labels << QString::number(b.fromMs, 'f', 6); // the category's name, not shown
    }
    // A bar's edges to the µs and its count, where the pointer rests.
    const auto bins = r.intervals;
    connect(set, &QBarSet::hovered, this, [this, bins](bool over, int index) {
        if (!over || index < 0 || index >= int(bins.size())) {
            QToolTip::hideText();
            return;
        }
        const auto &b = bins[size_t(index)];
        QToolTip::showText(QCursor::pos(),
                           (std::isfinite(b.toMs) ? tr("%1 to %2 ms: %n frame(s)", nullptr, int(b.count))
                                                        .arg(b.fromMs, 0, 'f', 3)
                                                        .arg(b.toMs, 0, 'f', 3)
                                                  : tr("%1 ms or more: %n frame(s)", nullptr, int(b.count)).arg(b.fromMs, 0, 'f', 3)),
                           this);
    });
    auto *series = new QBarSeries;
    series->append(set);
    m_histogram->addSeries(series);
    auto *x = new QBarCategoryAxis;
    x->append(labels);
    x->setLabelsVisible(false);
    x->setLineVisible(false);
    x->setGridLineVisible(false);
    auto *y = new QValueAxis;
    y->setTitleText(tr("frames"));
    m_histogram->addAxis(x, Qt::AlignBottom);
    m_histogram->addAxis(y, Qt::AlignLeft);
    series->attachAxis(x);
    series->attachAxis(y);
    if (!r.intervals.empty()) {
        // Equal bins from the first one's lower edge; the last may be "this or more".
        const auto &first = r.intervals.front();
        const double width = std::isfinite(first.toMs) ? first.toMs - first.fromMs : 1.0;
        const double lo = first.fromMs, hi = lo + width * double(r.intervals.size());
        auto *ms = new QValueAxis;
        ms->setRange(lo, hi);
        const double step = plot::AxisScaling::niceStep(hi - lo, 6); // six parts at most
        ms->setTickType(QValueAxis::TicksDynamic);
        ms->setTickAnchor(std::ceil(lo / step) * step);
        ms->setTickInterval(step);
        ms->setLabelFormat(QStringLiteral("%g"));
        ms->setGridLineVisible(false);
        const auto &last = r.intervals.back();
        ms->setTitleText(std::isfinite(last.toMs) ? tr("interval, ms")
                                                  : tr("interval, ms (the last bar: %1 ms or more)").arg(last.fromMs, 0, 'g', 3));
        m_histogram->addAxis(ms, Qt::AlignBottom);
    }
    double top = 1;
    for (const auto &b : r.intervals)
        top = std::max(top, double(b.count));
    y->setRange(0, top);
}

void AnalysisWindow::fillAllan(const record::SampleAnalyzer::Result &r)
{
    m_allan->removeAllSeries();
    for (QAbstractAxis *axis : m_allan->axes())
        m_allan->removeAxis(axis);
    auto *x = new QLogValueAxis;
    x->setTitleText(tr("τ, s"));
    x->setLabelFormat(QStringLiteral("%g"));
    auto *y = new QLogValueAxis;
    y->setTitleText(tr("σ(τ)"));
    y->setLabelFormat(QStringLiteral("%g"));
    m_allan->addAxis(x, Qt::AlignBottom);
    m_allan->addAxis(y, Qt::AlignLeft);
    double lo = INFINITY, hi = 0, tLo = INFINITY, tHi = 0;
    for (const auto &a : r.axes) {
        auto *series = new QLineSeries;
        series->setName(QString::fromStdString(a.name));
        for (const auto &p : a.curve) {
            if (p.adev <= 0)
                continue;
            series->append(p.tau, p.adev);
            lo = std::min(lo, p.adev);
            hi = std::max(hi, p.adev);
            tLo = std::min(tLo, p.tau);
            tHi = std::max(tHi, p.tau);
        }
        m_allan->addSeries(series);
        series->attachAxis(x);
        series->attachAxis(y);
    }
    if (hi > 0) {
        x->setRange(tLo, tHi);
        y->setRange(lo / 2, hi * 2);
    }
}

} // namespace imudesk::ui
