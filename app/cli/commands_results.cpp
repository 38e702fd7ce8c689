// imudesk-cli results: what a results database holds (core/results), the station's SQLite file
// or the line's PostgreSQL server: a serial number's whole history, a plan's yield per firmware
// and fixture slot, every record since a date as CSV or JSON lines. And the line's upkeep: the
// server's schema and its stations' role (setup), a station's outbox sent now (upload).
#include "cli_context.h"
#include "core/results/results_store.h"
#include "core/results/results_uploader.h"

#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <QStandardPaths>

#include <cmath>

namespace imudesk::cli {

namespace {

const QString kUsage = QStringLiteral(
    "imudesk-cli results serial SN [--db FILE | --results URL] [--json]\n"
    "       imudesk-cli results yield --plan NAME [--since DATE] [--db FILE | --results URL] [--json]\n"
    "       imudesk-cli results export --since DATE [--format csv|jsonl] [--plan NAME] [--db FILE | --results URL]\n"
    "       imudesk-cli results upload --results URL [--db FILE] [--artifacts DIR]\n"
    "       imudesk-cli results setup --results URL [--station-role ROLE]");

QString csvField(const QString &s)
{
    if (!s.contains(QLatin1Char(',')) && !s.contains(QLatin1Char('"')) && !s.contains(QLatin1Char('\n'))
        && !s.contains(QLatin1Char('\r')))
        return s;
    QString q = s;
    q.replace(QLatin1Char('"'), QLatin1String("\"\""));
    return QLatin1Char('"') + q + QLatin1Char('"');
}

QString optionalNumber(const std::optional<double> &v)
{
    return v ? QString::number(*v, 'g', 12) : QString();
}

QDateTime parseDate(const QString &text)
{
    QDateTime t = QDateTime::fromString(text, Qt::ISODate);
    if (!t.isValid())
        t = QDateTime(QDate::fromString(text, Qt::ISODate), QTime(0, 0), Qt::UTC);
    return t;
}

QJsonObject countsJson(const results::ResultsStore::Counts &c)
{
    QJsonObject o{{QStringLiteral("pass"), c.pass}, {QStringLiteral("fail"), c.fail}, {QStringLiteral("error"), c.error},
                  {QStringLiteral("aborted"), c.aborted}, {QStringLiteral("marginal"), c.marginal}};
    const double y = c.yield();
    o.insert(QStringLiteral("yield"), std::isnan(y) ? QJsonValue() : QJsonValue(y));
    return o;
}

QString countsText(const results::ResultsStore::Counts &c)
{
    const double y = c.yield();
    return QStringLiteral("%1 pass (%6 marginal), %2 fail, %3 error, %4 aborted; yield %5")
        .arg(c.pass).arg(c.fail).arg(c.error).arg(c.aborted)
        .arg(std::isnan(y) ? QStringLiteral("-") : QStringLiteral("%1 %").arg(100.0 * y, 0, 'f', 1))
        .arg(c.marginal);
}

} // namespace

int cmdResults(const QStringList &args)
{
    QCommandLineParser p;
    p.addOption({QStringLiteral("db"), QStringLiteral("The results database (default: results.sqlite here; the station "
                                                      "window writes it in its report folder, `station --report DIR` "
                                                      "in DIR)."), QStringLiteral("FILE")});
    p.addOption({QStringLiteral("plan"), QStringLiteral("yield: the plan's name."), QStringLiteral("NAME")});
    p.addOption({QStringLiteral("since"), QStringLiteral("yield: modules started on or after DATE (2026-11-01 or an ISO time)."),
                 QStringLiteral("DATE")});
    p.addOption({QStringLiteral("json"), QStringLiteral("One JSON object.")});
    p.addOption({QStringLiteral("results"),
                 QStringLiteral("The line's database, postgresql://user[:password]@host[:port]/db (?host=/socket/dir for a "
                                "local socket); read instead of --db."),
                 QStringLiteral("URL")});
    p.addOption({QStringLiteral("format"), QStringLiteral("export: csv (one row per measurement) or jsonl (one record per line)."),
                 QStringLiteral("csv|jsonl")});
    p.addOption({QStringLiteral("artifacts"), QStringLiteral("upload: shared folder the reports are copied to."),
                 QStringLiteral("DIR")});
    p.addOption({QStringLiteral("station-role"),
                 QStringLiteral("setup: an existing login role given SELECT and INSERT on the results, nothing else."),
                 QStringLiteral("ROLE")});
    p.addPositionalArgument(QStringLiteral("serial SN | yield | export | upload | setup"), QStringLiteral("What to do."));
    if (!parseArgs(p, args, kUsage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    const QString what = pos.value(0);
    const bool known = (what == QLatin1String("serial") && pos.size() == 2)
        || (pos.size() == 1 && QStringList{QStringLiteral("yield"), QStringLiteral("export"), QStringLiteral("upload"),
                                           QStringLiteral("setup")}.contains(what));
    if (!known)
        return fail(QStringLiteral("usage: %1").arg(kUsage), ExitUsage);
    // Without --db and --results: what the station window was set to (its line database, else
    // results.sqlite in its report folder), unless this folder holds a results.sqlite.
    const bool chosen = p.isSet(QStringLiteral("db")) || p.isSet(QStringLiteral("results"));
    QSettings window(QStringLiteral("ImuDesk"), QStringLiteral("ImuDesk"));
    const QString server = chosen || QFileInfo::exists(QStringLiteral("results.sqlite"))
        ? p.value(QStringLiteral("results"))
        : window.value(QStringLiteral("station/v1/lineDatabase")).toString();
    if (!server.isEmpty() && !results::ResultsStore::isServerUrl(server))
        return fail(QStringLiteral("--results wants a postgresql:// URL"), ExitUsage);
    if ((what == QLatin1String("upload") || what == QLatin1String("setup")) && server.isEmpty())
        return fail(QStringLiteral("%1 needs --results postgresql://...").arg(what), ExitUsage);
    QString db = p.isSet(QStringLiteral("db")) ? p.value(QStringLiteral("db")) : QStringLiteral("results.sqlite");
    if (!chosen && !QFileInfo::exists(db)) {
        QString folder = window.value(QStringLiteral("station/v1/reportFolder")).toString();
        if (folder.isEmpty())
            folder = QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation)).filePath(QStringLiteral("ImuDesk/station"));
        db = QDir(folder).filePath(QLatin1String(results::ResultsStore::kFileName));
    }
    const bool fromServer = !server.isEmpty() && what != QLatin1String("upload");
    if (!fromServer && !QFileInfo::exists(db))
        return fail(QStringLiteral("no results database at %1: give its path with --db (the station window writes "
                                   "results.sqlite in its report folder, `imudesk-cli station --report DIR` in DIR)")
                        .arg(db));
    results::ResultsStore store;
    QString error;
    if (!store.open(fromServer ? server : db, &error))
        return fail(error);
    const QString source = results::ResultsStore::displayLocation(store.location());
    const bool json = p.isSet(QStringLiteral("json"));
    if (what == QLatin1String("setup")) {
        out(QStringLiteral("%1: schema %2").arg(source).arg(store.schemaVersion()));
        if (p.isSet(QStringLiteral("station-role"))) {
            if (!store.grantStationRole(p.value(QStringLiteral("station-role")), &error))
                return fail(error);
            out(QStringLiteral("role %1 may read and insert results, and nothing else").arg(p.value(QStringLiteral("station-role"))));
        }
        return ExitOk;
    }
    if (what == QLatin1String("upload")) {
        results::ResultsStore line;
        if (!line.open(server, &error))
            return fail(error);
        int sent = 0;
        const bool ok = results::uploadPending(store, line, p.value(QStringLiteral("artifacts")), 100, &sent, &error);
        const int left = store.pendingCount();
        out(QStringLiteral("%1 uploaded to %2, %3 waiting").arg(sent).arg(results::ResultsStore::displayLocation(server)).arg(left));
        return ok ? ExitOk : fail(error);
    }
    if (what == QLatin1String("export")) {
        if (!p.isSet(QStringLiteral("since")))
            return fail(QStringLiteral("export needs --since DATE"), ExitUsage);
        const QString format = p.value(QStringLiteral("format")).isEmpty() ? QStringLiteral("csv") : p.value(QStringLiteral("format"));
        if (format != QLatin1String("csv") && format != QLatin1String("jsonl"))
            return fail(QStringLiteral("--format is csv or jsonl"), ExitUsage);
        results::ResultsStore::Filter f;
        f.from = parseDate(p.value(QStringLiteral("since")));
        if (!f.from.isValid())
            return fail(QStringLiteral("--since wants a date (2026-11-01) or an ISO time"), ExitUsage);
        f.plan = p.value(QStringLiteral("plan"));
        f.limit = 0;
        const auto records = store.records(f, &error);
        if (!error.isEmpty())
            return fail(error);
        if (format == QLatin1String("jsonl")) {
            for (const auto &m : records)
                outRaw(QJsonDocument(m.toJson()).toJson(QJsonDocument::Compact).toStdString());
            return records.empty() ? ExitNotFound : ExitOk;
        }
        out(QStringLiteral("module_uuid,run_uuid,station_id,plan,serial,product,slot,firmware_before,firmware_after,attempt,"
                           "module_outcome,marginal,started,step,measurement,value,unit,comparator,low,high,marginal_low,"
                           "marginal_high,outcome"));
        for (const auto &m : records)
            for (const auto &v : m.measurements)
                out(QStringList{m.uuid, m.run.uuid, csvField(m.run.stationId), csvField(m.run.planName), csvField(m.serial),
                                csvField(m.product), csvField(m.slot), csvField(m.firmwareBefore),
                                csvField(m.firmwareAfter), QString::number(m.attempt), results::outcomeKey(m.outcome),
                                m.marginal ? QStringLiteral("1") : QStringLiteral("0"),
                                m.started.toUTC().toString(Qt::ISODateWithMs), QString::number(v.step), csvField(v.name),
                                QString::number(v.value, 'g', 12), csvField(v.unit), v.comparator, optionalNumber(v.low),
                                optionalNumber(v.high), optionalNumber(v.marginalLow), optionalNumber(v.marginalHigh),
                                v.marginal && v.outcome == results::Outcome::Pass ? QStringLiteral("PASS_MARGINAL")
                                                                                   : results::outcomeKey(v.outcome)}
                        .join(QLatin1Char(',')));
        return records.empty() ? ExitNotFound : ExitOk;
    }
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
            return h.empty() ? ExitNotFound : ExitOk;
        }
        if (h.empty()) {
            // stderr, like every other "nothing" of the CLI: stdout stays the results (none).
            fail(QStringLiteral("%1: no results in %2").arg(pos[1], source), ExitNotFound);
            return ExitNotFound;
        }
        for (const auto &m : h) {
            out(QStringLiteral("%1  %2  attempt %3  %4  plan \"%5\"  slot %6  firmware %7%8  station %9")
                    .arg(m.started.toUTC().toString(Qt::ISODate),
                         results::outcomeKey(m.outcome) + (m.marginal ? QStringLiteral(" (marginal)") : QString()))
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
        since = parseDate(p.value(QStringLiteral("since")));
        if (!since.isValid())
            return fail(QStringLiteral("--since wants a date (2026-11-01) or an ISO time"), ExitUsage);
    }
    const results::ResultsStore::Yield y = store.yield(p.value(QStringLiteral("plan")), since, &error);
    if (!error.isEmpty())
        return fail(error);
    const results::ResultsStore::Counts &t = y.total;
    const bool none = t.pass + t.fail + t.error + t.aborted == 0;
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
        return none ? ExitNotFound : ExitOk;
    }
    if (none)
        return fail(QStringLiteral("plan \"%1\": no modules in %2").arg(p.value(QStringLiteral("plan")), source), ExitNotFound);
    out(QStringLiteral("plan \"%1\": %2 (ERROR and ABORTED are not counted in the yield)")
            .arg(p.value(QStringLiteral("plan")), countsText(y.total)));
    for (const auto &[k, c] : y.byFirmware)
        out(QStringLiteral("  firmware %1: %2").arg(k.isEmpty() ? QStringLiteral("?") : k, countsText(c)));
    for (const auto &[k, c] : y.bySlot)
        out(QStringLiteral("  slot %1: %2").arg(k, countsText(c)));
    return ExitOk;
}

} // namespace imudesk::cli
