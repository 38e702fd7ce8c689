// imudesk-cli station PLAN.json PORT[,PORT...]: the production station without the window. The
// plan runs on every port at once (station::StationRunner, one engine session per module);
// progress goes to stderr, one result line per module to stdout (--json: the module's JSON
// object, the same as a line of summary.jsonl, then a summary object). With --report DIR the
// run folder gets plan.json, summary.jsonl, summary.csv, the evidence recordings and a PDF per
// module, and the station's results database results.sqlite (in DIR itself, where the user looks
// for it; the window keeps it in its report folder, which holds its run folders); a DIR that
// already holds a run of the same plan is appended to (re-runs). The exit
// code is 0 only when every module passed.
#include "cli_context.h"
#include "reports/station_report.h"
#include "core/results/results_uploader.h"
#include "core/station/station_runner.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cstdio>

namespace imudesk::cli {

namespace {
const QString kUsage = QStringLiteral("imudesk-cli station PLAN.json PORT[,PORT...] [--report DIR] [--baud B] [--json]\n"
                                      "       [--results postgresql://...] [--artifacts DIR] [--station-id ID] [--operator NAME]\n"
                                      "       [--upload-wait S]");

void progressLine(const QString &line)
{
    std::fprintf(stderr, "%s\n", line.toLocal8Bit().constData());
    std::fflush(stderr);
}
} // namespace

int cmdStation(const QStringList &args)
{
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral("Runs a station test plan on several modules at once."));
    p.addPositionalArgument(QStringLiteral("plan"), QStringLiteral("The test plan (JSON, see docs/examples)."));
    p.addPositionalArgument(QStringLiteral("ports"), QStringLiteral("Serial ports, separated by commas or spaces."));
    p.addOption({QStringLiteral("report"),
                 QStringLiteral("Run folder for the reports and results.sqlite (created; an existing run of the same plan "
                                "is appended to)."),
                 QStringLiteral("DIR")});
    p.addOption({QStringLiteral("baud"), QStringLiteral("Baud rate of every module (default: detect)."),
                 QStringLiteral("B")});
    p.addOption({QStringLiteral("json"), QStringLiteral("One JSON object per module, then a summary object.")});
    p.addOption({QStringLiteral("results"),
                 QStringLiteral("The line's results database (postgresql://user@host/db); results go to the station's "
                                "results.sqlite first and are uploaded from there (needs --report)."),
                 QStringLiteral("URL")});
    p.addOption({QStringLiteral("artifacts"), QStringLiteral("Shared folder the reports are copied to on upload."),
                 QStringLiteral("DIR")});
    p.addOption({QStringLiteral("station-id"), QStringLiteral("The station's name in the records (default: the host name)."),
                 QStringLiteral("ID")});
    p.addOption({QStringLiteral("operator"), QStringLiteral("The operator's name in the records (default: $USER)."),
                 QStringLiteral("NAME")});
    p.addOption({QStringLiteral("upload-wait"),
                 QStringLiteral("Seconds to wait at the end for the upload (default 30); what is left waits in "
                                "results.sqlite for the next run or `results upload`."),
                 QStringLiteral("S")});
    if (!parseArgs(p, args, kUsage))
        return ExitUsage;
    const QStringList pos = p.positionalArguments();
    if (pos.size() < 2)
        return fail(QStringLiteral("station needs a plan and at least one port (usage: %1)").arg(kUsage), ExitUsage);
    QStringList ports;
    for (const QString &a : pos.mid(1))
        for (const QString &port : a.split(QLatin1Char(','), Qt::SkipEmptyParts))
            ports << port.trimmed();
    if (ports.removeDuplicates() > 0)
        return fail(QStringLiteral("a port is named twice"), ExitUsage);
    bool ok = true;
    const int baud = p.isSet(QStringLiteral("baud")) ? p.value(QStringLiteral("baud")).toInt(&ok) : 0;
    if (!ok || baud < 0)
        return fail(QStringLiteral("--baud needs a positive number"), ExitUsage);

    QString error;
    const auto plan = station::TestPlan::load(pos.at(0), &error);
    if (!plan)
        return fail(QStringLiteral("%1: %2").arg(pos.at(0), error));
    if (const QStringList problems = plan->problems(); !problems.isEmpty())
        return fail(QStringLiteral("%1: %2").arg(pos.at(0), problems.join(QStringLiteral("; "))));

    station::StationRunner runner(*plan, ports);
    runner.setBaud(baud);
    runner.setStation(p.value(QStringLiteral("station-id")), p.value(QStringLiteral("operator")));
    const double uploadWaitS = p.isSet(QStringLiteral("upload-wait")) ? p.value(QStringLiteral("upload-wait")).toDouble(&ok) : 30.0;
    if (!ok || uploadWaitS < 0)
        return fail(QStringLiteral("--upload-wait needs a number of seconds"), ExitUsage);
    if (p.isSet(QStringLiteral("results"))) {
        if (!p.isSet(QStringLiteral("report")))
            return fail(QStringLiteral("--results needs --report DIR: results are kept on the station first"), ExitUsage);
        if (!results::ResultsStore::isServerUrl(p.value(QStringLiteral("results"))))
            return fail(QStringLiteral("--results wants a postgresql:// URL"), ExitUsage);
        results::UploaderOptions line;
        line.server = p.value(QStringLiteral("results"));
        line.artifactFolder = p.value(QStringLiteral("artifacts"));
        runner.setLineDatabase(line);
    }
    if (p.isSet(QStringLiteral("report"))) {
        // The run folder the user named holds the results database too (not its parent folder).
        const QString report = p.value(QStringLiteral("report"));
        if (!runner.setRunFolder(report, &error, report))
            return fail(error);
        if (runner.resultsStore().isOpen())
            progressLine(QStringLiteral("results database: %1")
                             .arg(QDir::toNativeSeparators(runner.resultsStore().location())));
        runner.setReportWriter(&ui::writeStationReport);
    }
    const bool json = p.isSet(QStringLiteral("json"));
    // Progress: a line whenever a module starts another step.
    std::vector<int> lastStep(size_t(ports.size()), -2);
    QObject::connect(&runner, &station::StationRunner::moduleChanged, [&](int i) {
        const auto &m = runner.module(i);
        if (m.currentStep == lastStep[size_t(i)] || m.currentStep < 0)
            return;
        lastStep[size_t(i)] = m.currentStep;
        progressLine(QStringLiteral("%1: step %2/%3 %4")
                         .arg(m.port)
                         .arg(m.currentStep + 1)
                         .arg(m.steps.size())
                         .arg(m.steps[size_t(m.currentStep)].title));
    });
    QObject::connect(&runner, &station::StationRunner::moduleFinished, [&](int i) {
        const auto &m = runner.module(i);
        if (json) {
            out(QString::fromUtf8(QJsonDocument(m.toJson()).toJson(QJsonDocument::Compact)));
            return;
        }
        QString line = QStringLiteral("%1 %2 %3 %4").arg(station::verdictKey(m.verdict).toUpper(), m.port,
                                                         m.product.isEmpty() ? QStringLiteral("-") : m.product,
                                                         m.serial.isEmpty() ? QStringLiteral("-") : m.serial);
        if (!m.firmwareAfter.isEmpty())
            line += QStringLiteral(" firmware %1->%2").arg(m.firmware, m.firmwareAfter);
        if (const QString f = m.failureSummary(); !f.isEmpty())
            line += QStringLiteral(": ") + f;
        if (!m.reportPath.isEmpty())
            line += QStringLiteral(" (report %1)").arg(QDir::toNativeSeparators(m.reportPath));
        out(line);
    });
    QEventLoop loop;
    QObject::connect(&runner, &station::StationRunner::finished, &loop, &QEventLoop::quit);
    bool cancelled = false;
    QTimer watch; // Ctrl+C: cancel every module, then wait for them to end
    QObject::connect(&watch, &QTimer::timeout, [&] {
        if (interrupted() && !cancelled) {
            cancelled = true;
            progressLine(QStringLiteral("interrupted: cancelling every module"));
            runner.cancel();
        }
    });
    watch.start(100);
    runner.start();
    if (runner.running())
        loop.exec();
    for (const QString &e : runner.reportErrors())
        progressLine(QStringLiteral("report: %1").arg(e));
    int waiting = 0;
    if (results::ResultsUploader *up = runner.uploader()) {
        // Give the uploader its chance to send the last modules; what it cannot send stays in
        // the station's database and goes with the next run or `results upload`. The outbox
        // itself says what is left (a pass that began before the last module was stored may
        // report none).
        QEventLoop wait;
        QTimer deadline;
        deadline.setSingleShot(true);
        QObject::connect(&deadline, &QTimer::timeout, &wait, &QEventLoop::quit);
        QObject::connect(up, &results::ResultsUploader::stateChanged, &wait, [&] {
            if (runner.resultsStore().pendingCount() == 0)
                wait.quit();
        });
        up->kick();
        deadline.start(int(uploadWaitS * 1000));
        if (runner.resultsStore().pendingCount() > 0)
            wait.exec();
        waiting = runner.resultsStore().pendingCount();
        progressLine(waiting == 0 ? QStringLiteral("results: every result uploaded to %1")
                                        .arg(results::ResultsStore::displayLocation(up->options().server))
                                  : QStringLiteral("results: %1 results waiting to upload to %2 (kept in %3)")
                                        .arg(waiting)
                                        .arg(results::ResultsStore::displayLocation(up->options().server),
                                             QDir::toNativeSeparators(up->options().outbox)));
    }
    const auto s = runner.summary();
    if (json)
        out(QString::fromUtf8(QJsonDocument(QJsonObject{{QStringLiteral("event"), QStringLiteral("summary")},
                                                        {QStringLiteral("passed"), s.passed},
                                                        {QStringLiteral("failed"), s.failed},
                                                        {QStringLiteral("frames_lost"), qint64(runner.framesLost())},
                                                        {QStringLiteral("waiting_upload"), waiting},
                                                        {QStringLiteral("run_folder"), runner.runFolder()},
                                                        {QStringLiteral("results_db"), runner.resultsStore().isOpen()
                                                                                           ? runner.resultsStore().location()
                                                                                           : QString()}})
                                  .toJson(QJsonDocument::Compact)));
    else
        out(QStringLiteral("%1 passed, %2 failed%3%4")
                .arg(s.passed)
                .arg(s.failed)
                .arg(runner.runFolder().isEmpty() ? QString()
                                                  : QStringLiteral("; reports in %1")
                                                        .arg(QDir::toNativeSeparators(runner.runFolder())))
                .arg(runner.resultsStore().isOpen() ? QStringLiteral("; results in %1")
                                                          .arg(QDir::toNativeSeparators(runner.resultsStore().location()))
                                                    : QString()));
    if (cancelled)
        return ExitInterrupted;
    return runner.allPassed() && runner.reportErrors().isEmpty() ? ExitOk : ExitFailure;
}

} // namespace imudesk::cli
