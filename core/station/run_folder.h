#pragma once
// The folder of one station run: the plan it ran (plan.json), one summary of every module
// tested (summary.jsonl: one JSON object per module and attempt; summary.csv: one row per
// step and measured value, the tidy form a spreadsheet filters), the evidence recordings
// and the per-module PDF reports. Opening a folder that already holds a run of the same plan
// appends to it: a module tested again gets the next attempt number, nothing is overwritten.
#include "core/station/station_result.h"
#include "core/station/test_plan.h"

#include <QCoreApplication>
#include <QString>

namespace imudesk::station {

class RunFolder {
    Q_DECLARE_TR_FUNCTIONS(imudesk::station::RunFolder)

public:
    static constexpr const char *kPlanFile = "plan.json";
    static constexpr const char *kJsonlFile = "summary.jsonl";
    static constexpr const char *kCsvFile = "summary.csv";

    // Creates the folder when needed and saves the plan into it (a folder holding another
    // plan is refused: its results would not compare).
    bool open(const QString &dir, const TestPlan &plan, QString *error);
    const QString &path() const { return m_dir; }
    // A new folder name under parent for a run starting now: "<plan name>-yyyyMMdd-HHmmss".
    static QString newRunPath(const QString &parent, const TestPlan &plan);

    // 1 + the attempts of this serial already in the summary.
    int nextAttempt(const QString &serial) const;
    QString evidencePath(const QString &port) const;
    QString reportPath(const ModuleResult &r) const;
    // Appends the module to summary.jsonl and summary.csv (with its header when new).
    bool append(const ModuleResult &r, QString *error);
    // openhtf/<module uuid>.json: the module's record in OpenHTF's JSON layout (result_record.h).
    bool writeOpenHtf(const QString &moduleUuid, const QJsonObject &record, QString *error);
    static constexpr const char *kOpenHtfDir = "openhtf";
    // Every module result in the summary, oldest first (for re-runs and tests).
    QList<QJsonObject> entries() const;

    static QString csvHeader();
    static QStringList csvRows(const ModuleResult &r);

private:
    QString m_dir;
};

} // namespace imudesk::station
