// The production station's state without its window (core/station/station_session.h, issue 54
// point 4): what it refuses and why, an in-process simulated tray of four HI14 modules (a noisy
// gyro, a wrong mounting, firmware 1.6.6, a good one) run with a short plan and counted in the
// summary line, a workspace asked for while its module is under test handed over after the test
// (at the tray's 115200 baud) and at once after it, the failed modules run again, and the
// settings remembered only when the session is told to remember.
#include "../common/station_plans.h"
#include "../common/test_main.h"
#include "core/station/station_session.h"

#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using station::StationSession;
using station::TestPlan;
using station::Verdict;

namespace {

// The tray's clocks run this much faster than real time.
constexpr double kTimeScale = 4.0;

TestPlan shortPlan()
{
    return test::shortTrayPlan(QStringLiteral("session test"));
}

} // namespace

class TstStationSession : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true); // QSettings in a folder of the tests'
        QVERIFY(m_dir.isValid());
    }

    void refusesWhatCannotRun()
    {
        StationSession s;
        s.setRemembering(false);
        QCOMPARE(s.summaryLine(), QStringLiteral("No run yet."));
        QString error;
        QVERIFY(!s.start({QStringLiteral("/dev/ttyUSB0")}, &error));
        QVERIFY2(error.contains(QStringLiteral("Open a test plan first")), qPrintable(error));
        QSignalSpy planChanged(&s, &StationSession::planChanged);
        s.setPlan(shortPlan(), QString());
        QCOMPARE(planChanged.count(), 1);
        QVERIFY(s.hasPlan());
        QVERIFY(!s.start({}, &error));
        QVERIFY2(error.contains(QStringLiteral("Check the ports")), qPrintable(error));
        TestPlan none = shortPlan();
        for (station::PlanStep &step : none.steps)
            step.enabled = false;
        if (!none.problems().isEmpty()) {
            s.setPlan(none, QString());
            QVERIFY(!s.start({QStringLiteral("/dev/ttyUSB0")}, &error));
            QVERIFY2(error.contains(QStringLiteral("cannot run")), qPrintable(error));
        }
        QVERIFY(!s.openPlan(m_dir.filePath(QStringLiteral("missing.json")), &error));
        QVERIFY2(error.contains(QStringLiteral("missing.json")), qPrintable(error));
        QVERIFY(!s.running());
        QVERIFY(!s.hasRunFolder());
    }

    void runsATrayAndCountsIt()
    {
        StationSession s;
        s.setRemembering(false);
        s.setReportFolder(m_dir.path());
        s.setSimulatedTrayInProcess(true, kTimeScale);
        QSignalSpy tray(&s, &StationSession::trayChanged);
        QString error;
        QVERIFY2(s.startSimulatedTray(4, true, &error), qPrintable(error));
        QCOMPARE(tray.count(), 1);
        QCOMPARE(s.simulatedPorts(), QStringList({QStringLiteral("sim:tray-1"), QStringLiteral("sim:tray-2"),
                                                  QStringLiteral("sim:tray-3"), QStringLiteral("sim:tray-4")}));
        QVERIFY(s.simulatedNote(QStringLiteral("sim:tray-1")).contains(QStringLiteral("noisy gyro")));
        QVERIFY(s.simulatedNote(QStringLiteral("sim:tray-4")).contains(QStringLiteral("a good module")));
        QCOMPARE(s.baudFor(QStringLiteral("sim:tray-2")), StationSession::kSimulatedBaud);

        s.setPlan(shortPlan(), QString());
        QSignalSpy started(&s, &StationSession::runStarted);
        QSignalSpy finished(&s, &StationSession::runFinished);
        QSignalSpy ready(&s, &StationSession::workspaceReady);
        QVERIFY2(s.start(s.simulatedPorts(), &error), qPrintable(error));
        QCOMPARE(started.count(), 1);
        QVERIFY(s.running());
        QVERIFY(s.runner()->runFolder().startsWith(m_dir.path()));
        // The tray cannot change under a run.
        QVERIFY(!s.startSimulatedTray(2, false, &error));
        QVERIFY2(error.contains(QStringLiteral("Wait for the run to end")), qPrintable(error));
        QCOMPARE(s.simulatedPorts().size(), 4);

        // The good module's workspace, asked for while it is under test: after its test.
        QTRY_VERIFY_WITH_TIMEOUT(s.runner()->module(3).verdict == Verdict::Running, 10000);
        s.openModule(3);
        QCOMPARE(ready.count(), 0);
        QVERIFY2(s.summaryLine().contains(QStringLiteral("the workspace of sim:tray-4 opens when its test has ended")),
                 qPrintable(s.summaryLine()));
        QTRY_VERIFY_WITH_TIMEOUT(!s.running(), 120000);
        QTRY_COMPARE(finished.count(), 1);
        QTRY_COMPARE(ready.count(), 1);
        QCOMPARE(ready.first().at(0).toString(), QStringLiteral("sim:tray-4"));
        QCOMPARE(ready.first().at(1).toInt(), StationSession::kSimulatedBaud);
        QCOMPARE(s.summaryLine(), QStringLiteral("1 passed · 3 failed · 0 running · 0 waiting"));
        QVERIFY(s.anyFailed());
        QVERIFY(s.hasRunFolder());
        // A finished module's workspace: at once.
        s.openModule(0);
        QCOMPARE(ready.count(), 2);
        QCOMPARE(ready.last().at(0).toString(), QStringLiteral("sim:tray-1"));

        // The failed modules again, into the same run folder.
        const QString folder = s.runner()->runFolder();
        QVERIFY(s.rerunFailed());
        QVERIFY(s.running());
        QCOMPARE(s.runner()->runFolder(), folder);
        QTRY_VERIFY_WITH_TIMEOUT(!s.running(), 120000);
        QCOMPARE(s.summaryLine(), QStringLiteral("1 passed · 3 failed · 0 running · 0 waiting"));
        QCOMPARE(started.count(), 1); // no new runner

        s.stopSimulatedTray();
        QVERIFY(s.simulatedPorts().isEmpty());
        QCOMPARE(tray.count(), 2);
    }

    void remembersOnlyWhenAsked()
    {
        QSettings().remove(QLatin1String(station::StationSettings::kReportFolderKey));
        {
            StationSession s;
            s.setRemembering(false);
            s.setReportFolder(m_dir.filePath(QStringLiteral("not-kept")));
            QCOMPARE(s.reportFolder(), m_dir.filePath(QStringLiteral("not-kept")));
        }
        QVERIFY(!QSettings().contains(QLatin1String(station::StationSettings::kReportFolderKey)));
        {
            StationSession s;
            s.setReportFolder(m_dir.path());
            s.setLineDatabase(QStringLiteral("postgresql://line@db/results"), m_dir.path());
        }
        StationSession later;
        later.loadSettings();
        QCOMPARE(later.reportFolder(), m_dir.path());
        QCOMPARE(later.settings().lineDatabase, QStringLiteral("postgresql://line@db/results"));
        QSettings().remove(QLatin1String(station::StationSettings::kReportFolderKey));
        QSettings().remove(QLatin1String(station::StationSettings::kLineDatabaseKey));
        QSettings().remove(QLatin1String(station::StationSettings::kArtifactFolderKey));
    }

private:
    QTemporaryDir m_dir;
};

IMUDESK_TEST_GUILESS_MAIN(TstStationSession)
#include "tst_station_session.moc"
