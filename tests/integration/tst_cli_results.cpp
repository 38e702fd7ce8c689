// imudesk-cli results over a station's results.sqlite (issue 53 point 17a): a query that finds
// something exits 0, one that finds nothing exits 4 (ExitNotFound, docs/CLI.md), so a
// script tells "no such module" from a hit and from an error (1) or a usage mistake (2).
#include "../common/cli_run.h"
#include "../common/result_records.h"
#include "../common/test_main.h"
#include "core/results/results_store.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

namespace {
using imudesk::test::CliResult;
constexpr int kNotFound = 4;
} // namespace

class TstCliResults : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_db;

    CliResult results(QStringList args)
    {
        args.prepend(QStringLiteral("results"));
        args << QStringLiteral("--db") << m_db;
        return imudesk::test::runCli(args, 30000);
    }

private Q_SLOTS:
    void initTestCase()
    {
        using namespace imudesk;
        QVERIFY(m_dir.isValid());
        m_db = m_dir.filePath(QStringLiteral("results.sqlite"));
        results::ResultsStore store;
        QString error;
        QVERIFY2(store.open(m_db, &error), qPrintable(error));
        const results::RunRecord run = test::sampleRun(QStringLiteral("HI14 incoming"));
        QVERIFY2(store.commit(test::sampleModule(run, QStringLiteral("SN0042"), results::Outcome::Pass), &error),
                 qPrintable(error));
    }

    void serialFound()
    {
        const CliResult r = results({QStringLiteral("serial"), QStringLiteral("SN0042")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QLatin1String("HI14 incoming")));
    }

    void serialUnknown()
    {
        const CliResult r = results({QStringLiteral("serial"), QStringLiteral("UNKNOWN")});
        QCOMPARE(r.code, kNotFound);
        QVERIFY2(r.err.contains(QLatin1String("UNKNOWN: no results")), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }

    void serialUnknownJson()
    {
        const CliResult r = results({QStringLiteral("serial"), QStringLiteral("UNKNOWN"), QStringLiteral("--json")});
        QCOMPARE(r.code, kNotFound);
        QCOMPARE(r.json().value(QStringLiteral("serial")).toString(), QStringLiteral("UNKNOWN"));
        QVERIFY(r.json().value(QStringLiteral("attempts")).toArray().isEmpty());
    }

    void yieldOfUnknownPlan()
    {
        const CliResult known = results({QStringLiteral("yield"), QStringLiteral("--plan"), QStringLiteral("HI14 incoming")});
        QVERIFY2(known.code == 0, qPrintable(known.err));
        const CliResult r = results({QStringLiteral("yield"), QStringLiteral("--plan"), QStringLiteral("no such plan")});
        QCOMPARE(r.code, kNotFound);
        const CliResult json = results({QStringLiteral("yield"), QStringLiteral("--plan"), QStringLiteral("no such plan"),
                                        QStringLiteral("--json")});
        QCOMPARE(json.code, kNotFound);
    }

    void exportOfNothing()
    {
        const CliResult all = results({QStringLiteral("export"), QStringLiteral("--since"), QStringLiteral("2020-01-01")});
        QVERIFY2(all.code == 0, qPrintable(all.err));
        for (const char *format : {"csv", "jsonl"}) {
            const CliResult r = results({QStringLiteral("export"), QStringLiteral("--since"), QStringLiteral("2099-01-01"),
                                         QStringLiteral("--format"), QString::fromLatin1(format)});
            QCOMPARE(r.code, kNotFound);
        }
    }

    // A database that is not there stays an error (1), not "nothing found".
    void missingDatabaseIsAnError()
    {
        const CliResult r = imudesk::test::runCli({QStringLiteral("results"), QStringLiteral("serial"), QStringLiteral("X"),
                                                   QStringLiteral("--db"), m_dir.filePath(QStringLiteral("none.sqlite"))},
                                                  30000);
        QCOMPARE(r.code, 1);
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstCliResults)
#include "tst_cli_results.moc"
