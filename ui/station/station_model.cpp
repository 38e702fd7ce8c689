#include "ui/station/station_model.h"

#include "core/station/station_runner.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace imudesk::ui {

using station::ModuleResult;
using station::Verdict;

StationModel::StationModel(QObject *parent) : QAbstractListModel(parent)
{
    m_clock.setInterval(kRefreshMs);
    connect(&m_clock, &QTimer::timeout, this, [this] { refresh(); });
}

void StationModel::setRunner(const station::StationRunner *runner)
{
    beginResetModel();
    m_runner = runner;
    m_rows.clear();
    if (runner)
        for (int i = 0; i < runner->moduleCount(); ++i)
            m_rows.push_back(rowFor(runner->module(i)));
    endResetModel();
    // The clock runs only while there is something to read.
    if (runner)
        m_clock.start();
    else
        m_clock.stop();
}

int StationModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

QVariant StationModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_rows.size()))
        return {};
    const Row &row = m_rows[size_t(index.row())];
    switch (role) {
    case Qt::DisplayRole:
    case PortRole: return row.result.port;
    case SerialRole: return row.result.serial;
    case ProductRole: return row.result.product;
    case StepRole: return row.step;
    case ProgressRole: return row.result.progress;
    case VerdictRole: return int(row.result.verdict);
    case VerdictTextRole: return row.verdictText;
    case FailureRole: return row.failure;
    case Qt::ToolTipRole: return row.toolTip;
    default: return {};
    }
}

QHash<int, QByteArray> StationModel::roleNames() const
{
    QHash<int, QByteArray> names = QAbstractListModel::roleNames();
    names.insert(PortRole, "port");
    names.insert(SerialRole, "serial");
    names.insert(ProductRole, "product");
    names.insert(StepRole, "step");
    names.insert(ProgressRole, "progress");
    names.insert(VerdictRole, "verdict");
    names.insert(VerdictTextRole, "verdictText");
    names.insert(FailureRole, "failure");
    return names;
}

QString StationModel::stepText(const ModuleResult &r)
{
    switch (r.verdict) {
    case Verdict::Pending: return tr("waiting to start");
    case Verdict::Running:
        if (r.currentStep >= 0 && r.currentStep < int(r.steps.size()))
            return r.steps[size_t(r.currentStep)].title;
        return tr("connecting…");
    case Verdict::Fail: {
        const int failed = r.failedStep();
        return failed >= 0 ? tr("failed: %1").arg(r.steps[size_t(failed)].title) : tr("failed");
    }
    case Verdict::Pass: return tr("every step passed");
    case Verdict::Skipped: return tr("not tested");
    }
    return {};
}

QString StationModel::resultText(const ModuleResult &r)
{
    QStringList lines;
    lines << tr("%1: %2").arg(r.port, station::verdictText(r.verdict));
    if (!r.serial.isEmpty() || !r.product.isEmpty())
        lines << tr("Serial %1 · %2 · firmware %3")
                     .arg(r.serial.isEmpty() ? tr("(none)") : r.serial, r.product.isEmpty() ? tr("(none)") : r.product,
                          r.firmware.isEmpty() ? tr("(none)") : r.firmware);
    if (!r.firmwareAfter.isEmpty())
        lines << tr("Firmware after the update: %1").arg(r.firmwareAfter);
    for (const station::StepResult &s : r.steps) {
        if (s.verdict == Verdict::Pending)
            continue;
        QString line = tr("%1: %2").arg(s.title, station::verdictText(s.verdict));
        if (!s.detail.isEmpty())
            line += tr(" (%1)").arg(s.detail);
        lines << line;
        // Every value with its unit and limit, as the report lists them.
        for (const station::Measurement &m : s.values) {
            const QString value = QStringLiteral("%1 %2").arg(m.value, 0, 'g', 4).arg(m.unit).trimmed();
            lines << (m.limit.isEmpty() ? tr("    %1 = %2").arg(m.name, value)
                                        : tr("    %1 = %2 (limit %3)%4")
                                              .arg(m.name, value, m.limit,
                                                   !m.ok ? tr(" ✗") : m.marginal ? tr(" (marginal)") : QString()));
        }
    }
    if (!r.reportPath.isEmpty())
        lines << tr("Report: %1").arg(r.reportPath);
    return lines.join(QLatin1Char('\n'));
}

StationModel::Row StationModel::rowFor(const ModuleResult &r)
{
    Row row;
    row.result = r;
    row.step = stepText(r);
    row.verdictText = r.verdict == Verdict::Pass && r.marginal() ? tr("%1 (marginal)").arg(station::verdictText(r.verdict))
                                                                 : station::verdictText(r.verdict);
    row.failure = r.failureSummary();
    row.progressPermille = int(std::lround(std::clamp(r.progress, 0.0, 1.0) * 1000));
    row.toolTip = resultText(r);
    return row;
}

bool StationModel::sameShown(const Row &a, const Row &b)
{
    // What a tile or its tooltip shows (the tooltip lists every step's values as they end).
    return a.step == b.step && a.verdictText == b.verdictText && a.failure == b.failure
        && a.progressPermille == b.progressPermille && a.toolTip == b.toolTip;
}

void StationModel::refresh(bool all)
{
    if (!m_runner) {
        // The runner went away under the model: show nothing rather than stale modules.
        if (!m_rows.empty())
            setRunner(nullptr);
        return;
    }
    if (m_runner->moduleCount() != int(m_rows.size())) {
        setRunner(m_runner);
        Q_EMIT refreshed();
        return;
    }
    bool any = false;
    for (int i = 0; i < int(m_rows.size()); ++i) {
        Row row = rowFor(m_runner->module(i));
        if (!all && sameShown(row, m_rows[size_t(i)])) {
            m_rows[size_t(i)].result = std::move(row.result); // the latest values, nothing shown changed
            continue;
        }
        m_rows[size_t(i)] = std::move(row);
        any = true;
        Q_EMIT dataChanged(index(i), index(i));
    }
    if (any)
        Q_EMIT refreshed();
}

} // namespace imudesk::ui
