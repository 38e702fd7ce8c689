#pragma once
// Result records for the results database's tests and benchmark (issue 38): a run of a station
// and a module of it with two steps, a measurement with a limit, one for information, and the
// PDF artifact; a failed module's measurement is outside its limit.
#include "core/results/result_record.h"

namespace imudesk::test {

inline results::RunRecord sampleRun(const QString &plan = QStringLiteral("HI14 incoming"))
{
    using namespace results;
    RunRecord r;
    r.uuid = newUuid();
    r.stationId = QStringLiteral("bench-3");
    r.operatorName = QStringLiteral("li");
    r.planName = plan;
    r.planSha256 = QString(64, QLatin1Char('a'));
    r.imudeskVersion = QStringLiteral("0.1.0");
    r.started = QDateTime(QDate(2026, 11, 30), QTime(8, 0), Qt::UTC);
    return r;
}

inline results::ModuleRecord sampleModule(const results::RunRecord &r, const QString &serial, results::Outcome outcome,
                                          const QString &firmware = QStringLiteral("1.7.1"),
                                          const QString &slot = QStringLiteral("/dev/ttyUSB0"), int attempt = 1, int minute = 0)
{
    using namespace results;
    ModuleRecord m;
    m.uuid = newUuid();
    m.run = r;
    m.slot = slot;
    m.serial = serial;
    m.product = QStringLiteral("HI14R3");
    m.firmwareBefore = firmware;
    m.attempt = attempt;
    m.outcome = outcome;
    m.started = r.started.addSecs(60 * minute);
    m.finished = m.started.addSecs(30);
    m.steps.push_back({0, QStringLiteral("identify"), QStringLiteral("Identify"), Outcome::Pass, false, QStringLiteral("HI14R3"),
                       m.started, m.started.addSecs(1)});
    m.steps.push_back({1, QStringLiteral("static"), QStringLiteral("Static noise and bias"), outcome, false, QString(),
                       m.started.addSecs(1), m.finished});
    MeasurementRecord v;
    v.step = 1;
    v.name = QStringLiteral("gyro_std_x");
    v.value = outcome == Outcome::Fail ? 0.41 : 0.012;
    v.unit = QStringLiteral("°/s");
    v.comparator = QStringLiteral("LE");
    v.high = 0.05;
    v.outcome = outcome == Outcome::Fail ? Outcome::Fail : Outcome::Pass;
    m.measurements.push_back(v);
    MeasurementRecord info;
    info.step = 1;
    info.name = QStringLiteral("temperature");
    info.value = 31.5;
    info.unit = QStringLiteral("°C");
    info.comparator = QStringLiteral("INFO");
    m.measurements.push_back(info);
    m.artifacts.push_back({QStringLiteral("report"), QStringLiteral("application/pdf"), QString(64, QLatin1Char('b')),
                           QStringLiteral("/runs/x.pdf")});
    return m;
}

} // namespace imudesk::test
