#pragma once
// The modules of a production-station run (issue 22) as a list model, one row per port: what
// the station view's tiles show (port, serial number, product, the step under way, progress,
// verdict, what failed). It reads the runner on its own clock (kRefreshMs, 5 Hz) and reports
// only the rows that changed: a module's runner changes its result many times a second while
// it collects samples, and neither the tiles nor the summary need more than a few updates.
#include "core/station/station_result.h"
#include "core/station/station_runner.h"

#include <QAbstractListModel>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace imudesk::ui {

class StationModel : public QAbstractListModel {
    Q_OBJECT

public:
    static constexpr int kRefreshMs = 200; // the view clock: 5 Hz is plenty for a tray

    enum Role {
        PortRole = Qt::UserRole + 1,
        SerialRole,     // serial number, empty until the module answered
        ProductRole,    // product name (with its firmware), empty until the module answered
        StepRole,       // the step under way, or where it ended (translated)
        ProgressRole,   // double 0..1 of the whole plan
        VerdictRole,    // int(station::Verdict)
        VerdictTextRole,
        FailureRole,    // ModuleResult::failureSummary(): the failing step and its values
    };

    explicit StationModel(QObject *parent = nullptr);

    // The runner whose modules are shown (nullptr: none). The model does not own it; it
    // follows the runner's deletion by showing nothing.
    void setRunner(const station::StationRunner *runner);
    const station::StationRunner *runner() const { return m_runner; }

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QHash<int, QByteArray> roleNames() const override;

    // The module's result as of the last refresh (the tiles' tooltips list every step).
    const station::ModuleResult &result(int row) const { return m_rows[size_t(row)].result; }
    // The step text for a result: the one under way, the failing one, or the end (translated).
    static QString stepText(const station::ModuleResult &r);
    // Every step with its verdict, detail and values with their units and limits (a tooltip).
    static QString resultText(const station::ModuleResult &r);

    // Reads the runner now (the clock does this every kRefreshMs); `all` reports every row as
    // changed, e.g. after the language changed and the texts must be made again.
    void refresh(bool all = false);

Q_SIGNALS:
    // After a refresh that changed at least one row (dataChanged has been emitted for it).
    void refreshed();

private:
    struct Row {
        station::ModuleResult result;
        QString step, verdictText, failure, toolTip;
        int progressPermille = 0;
    };
    static Row rowFor(const station::ModuleResult &r);
    static bool sameShown(const Row &a, const Row &b);

    QPointer<const station::StationRunner> m_runner;
    std::vector<Row> m_rows;
    QTimer m_clock;
};

} // namespace imudesk::ui
