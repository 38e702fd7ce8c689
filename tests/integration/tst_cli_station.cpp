// imudesk-cli station --report DIR: where the run's files and the station's results database go.
// The database is kept inside the folder the user named (issue 53: it used to land in DIR's
// parent, /tmp for --report /tmp/run1), and the CLI says where it went. A port that cannot be
// opened ends its module quickly as ERROR, which is still committed to the database.
#include "../common/cli_run.h"
#include "../common/test_main.h"

#include "core/results/results_store.h"
#include "core/station/test_plan.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;

class TstCliStation : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void resultsDatabaseInTheNamedFolder_data()
    {
        QTest::addColumn<QString>("report"); // relative to a fresh temporary folder
        QTest::addColumn<bool>("json");
        QTest::newRow("new folder") << QStringLiteral("run1") << false;
        QTest::newRow("nested new folder, json") << QStringLiteral("line/tray-17") << true;
        QTest::newRow("folder that exists") << QStringLiteral("existing") << false;
    }
    void resultsDatabaseInTheNamedFolder()
    {
        QFETCH(QString, report);
        QFETCH(bool, json);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QVERIFY(QDir(dir.path()).mkpath(QStringLiteral("existing")));
        station::TestPlan plan;
        plan.name = QStringLiteral("where results go");
        plan.baseDir = dir.path();
        plan.steps.push_back(station::TestPlan::defaultStep(station::StepKind::Identify, {}));
        const QString planPath = dir.filePath(QStringLiteral("plan.json"));
        QString error;
        QVERIFY2(plan.save(planPath, &error), qPrintable(error));

        const QString reportDir = dir.filePath(report);
        QStringList args{QStringLiteral("station"), planPath, dir.filePath(QStringLiteral("no-such-port")),
                         QStringLiteral("--report"), reportDir};
        if (json)
            args << QStringLiteral("--json");
        const auto r = test::runCli(args, 60000);
        QVERIFY2(r.code == 1, qPrintable(r.out + r.err)); // the module could not be tested

        const QString db = QDir(reportDir).filePath(QLatin1String(results::ResultsStore::kFileName));
        QVERIFY2(QFileInfo::exists(db), qPrintable(QStringLiteral("no %1; stderr: %2").arg(db, r.err)));
        const QString parentDb =
            QDir(QFileInfo(reportDir).absolutePath()).filePath(QLatin1String(results::ResultsStore::kFileName));
        QVERIFY2(!QFileInfo::exists(parentDb), qPrintable(parentDb));
        // The module is in it.
        results::ResultsStore store;
        QVERIFY2(store.open(db, &error), qPrintable(error));
        QCOMPARE(store.search({}).size(), 1);
        // And the CLI said where it went.
        const QString shown = QDir::toNativeSeparators(QFileInfo(db).absoluteFilePath());
        QVERIFY2(r.err.contains(QStringLiteral("results database: ") + shown), qPrintable(r.err));
        if (json) {
            const QStringList lines = r.out.split(u'\n', Qt::SkipEmptyParts);
            QVERIFY(!lines.isEmpty());
            const QJsonObject summary = QJsonDocument::fromJson(lines.last().toUtf8()).object();
            QCOMPARE(summary.value(QStringLiteral("results_db")).toString(), QFileInfo(db).absoluteFilePath());
        } else {
            QVERIFY2(r.out.contains(QStringLiteral("results in ") + shown), qPrintable(r.out));
        }
        // `results` reads it from there.
        const auto history = test::runCli({QStringLiteral("results"), QStringLiteral("yield"), QStringLiteral("--plan"),
                                           plan.name, QStringLiteral("--db"), db, QStringLiteral("--json")});
        QVERIFY2(history.code == 0, qPrintable(history.err));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliStation)
#include "tst_cli_station.moc"
