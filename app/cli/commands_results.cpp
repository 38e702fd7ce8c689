// imudesk-cli results: what the station's results database holds (core/results): a serial
// number's whole history, a plan's yield per firmware and fixture slot.
#include "cli_context.h"
#include "core/results/results_store.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace imudesk::cli {

namespace {

const QString kUsage = QStringLiteral("imudesk-cli results serial SN [--db FILE] [--json]\n"
                                      "       imudesk-cli results yield --plan NAME [--since DATE] [--db FILE] [--json]");

QJsonObject countsJson(const results::ResultsStore::Counts &c)
{
    QJsonObject o{{QStringLiteral("pass"), c.pass}, {QStringLiteral("fail"), c.fail}, {QStringLiteral("error"), c.error},
                  {QStringLiteral("aborted"), c.aborted}};
    const double y = c.yield();
    o.insert(QStringLiteral("yield"), std::isnan(y) ? QJsonValue() : QJsonValue(y));
    return o;
}

QString countsText(const results::ResultsStore::Counts &c)
{
    const double y = c.yield();
    return QStringLiteral("%1 pass, %2 fail, %3 error, %4 aborted; yield %5")
        .arg(c.pass).arg(c.fail).arg(c.error).arg(c.aborted)
        .arg(std::isnan(y) ? QStringLiteral("-") : QStringLiteral("%1 %").arg(100.0 * y, 0, 'f', 1));
}

} // namespace

int cmdResults(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption({QStringLiteral("db"), QStringLiteral("The results database (default: results.sqlite here; a station "
                                                      "writes it beside its run folders)."), QStringLiteral("FILE")});
    p.addOption({QStringLiteral("plan"), QStringLiteral("yield: the plan's name."), QStringLiteral("NAME")});
    p.addOption({QStringLiteral("since"), QStringLiteral("yield: modules started on or after DATE (2026-11-01 or an ISO time)."),
                 QStringLiteral("DATE")});
    p.addOption({QStringLiteral("json"), QStringLiteral("One JSON object.")});
    p.addPositionalArgument(QStringLiteral("serial SN | yield"), QStringLiteral("What to show."));
    if (!parseArgs(p, args, kUsage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    const QString what = pos.value(0);
    if (!((what == QLatin1String("serial") && pos.size() == 2) || (what == QLatin1String("yield") && pos.size() == 1)))
        return fail(QStringLiteral("usage: %1").arg(kUsage), ExitUsage);
    const QString db = p.isSet(QStringLiteral("db")) ? p.value(QStringLiteral("db")) : QStringLiteral("results.sqlite");
    if (!QFileInfo::exists(db))
        return fail(QStringLiteral("no results database at %1: give its path with --db (a station writes results.sqlite "
                                   "beside its run folders)").arg(db));
    results::ResultsStore store;
    QString error;
    if (!store.open(db, &error))
        return fail(error);
    const bool json = p.isSet(QStringLiteral("json"));
    if (what == QLatin1String("serial")) {
        const std::vector<results::ModuleRecord> h = store.history(pos[1], &error);
        if (!error.isEmpty())
            return fail(error);
        if (json) {
            QJsonArray attempts;
            for (const auto &m : h)
                attempts.append(m.toJson());
            outRaw(QJsonDocument(QJsonObject{{QStringLiteral("serial"), pos[1]}, {QStringLiteral("attempts"), attempts}})
                       .toJson(QJsonDocument::Compact).toStdString());
            return ExitOk;
        }
        if (h.empty()) {
            out(QStringLiteral("%1: no results in %2").arg(pos[1], db));
            return ExitOk;
        }
        for (const auto &m : h) {
            out(QStringLiteral("%1  %2  attempt %3  %4  plan \"%5\"  slot %6  firmware %7%8  station %9")
                    .arg(m.started.toUTC().toString(Qt::ISODate), results::outcomeKey(m.outcome))
                    .arg(m.attempt)
                    .arg(m.product, m.run.planName, m.slot, m.firmwareBefore,
                         m.firmwareAfter.isEmpty() ? QString() : QStringLiteral(" -> ") + m.firmwareAfter, m.run.stationId));
            for (const auto &v : m.measurements)
                if (v.outcome == results::Outcome::Fail)
                    out(QStringLiteral("    failed: %1 = %2 %3 (limit %4 %5)")
                            .arg(v.name).arg(v.value).arg(v.unit, v.comparator).arg(v.high.value_or(0)));
            for (const auto &a : m.artifacts)
                out(QStringLiteral("    %1: %2").arg(a.kind, a.location));
        }
        return ExitOk;
    }
    if (!p.isSet(QStringLiteral("plan")))
        return fail(QStringLiteral("yield needs --plan NAME"), ExitUsage);
    QDateTime since;
    if (p.isSet(QStringLiteral("since"))) {
        since = QDateTime::fromString(p.value(QStringLiteral("since")), Qt::ISODate);
        if (!since.isValid())
            since = QDateTime(QDate::fromString(p.value(QStringLiteral("since")), Qt::ISODate), QTime(0, 0), Qt::UTC);
        if (!since.isValid())
            return fail(QStringLiteral("--since wants a date (2026-11-01) or an ISO time"), ExitUsage);
    }
    const results::ResultsStore::Yield y = store.yield(p.value(QStringLiteral("plan")), since, &error);
    if (!error.isEmpty())
        return fail(error);
    if (json) {
        QJsonObject firmware, slots;
        for (const auto &[k, c] : y.byFirmware)
            firmware.insert(k, countsJson(c));
        for (const auto &[k, c] : y.bySlot)
            slots.insert(k, countsJson(c));
        outRaw(QJsonDocument(QJsonObject{{QStringLiteral("plan"), p.value(QStringLiteral("plan"))},
                                         {QStringLiteral("total"), countsJson(y.total)},
                                         {QStringLiteral("by_firmware"), firmware},
                                         {QStringLiteral("by_slot"), slots}})
                   .toJson(QJsonDocument::Compact).toStdString());
        return ExitOk;
    }
    out(QStringLiteral("plan \"%1\": %2 (ERROR and ABORTED are not counted in the yield)")
            .arg(p.value(QStringLiteral("plan")), countsText(y.total)));
    for (const auto &[k, c] : y.byFirmware)
        out(QStringLiteral("  firmware %1: %2").arg(k.isEmpty() ? QStringLiteral("?") : k, countsText(c)));
    for (const auto &[k, c] : y.bySlot)
        out(QStringLiteral("  slot %1: %2").arg(k, countsText(c)));
    return ExitOk;
}

} // namespace imudesk::cli
