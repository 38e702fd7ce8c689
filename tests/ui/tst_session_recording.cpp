// Issue 36 in the window: the Time sync panel of a tab shows its clocks, and Device > Record all
// devices records every connected tab into one session folder that exports with the devices
// aligned. Two simulated modules of two families (an HI14 and an HEC495 compass), end to end.
#include "../common/ui_families.h"
#include "../common/test_main.h"
#include "itemmodels/clock_stats_model.h"
#include "record/replay_session.h"
#include "record/session_manifest.h"
#include "recording/recording_controls.h"
#include "recording/replay_controls.h"
#include "recording/session_recording_window.h"
#include "workspace/device_workspace.h"
#include "workspace/main_window.h"
#include "workspace/port_choice.h"
#include "workspace/tool_actions.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QPushButton>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using ui::MainWindow;

class TstSessionRecording : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void recordAllDevicesAndTheirClocks()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.resize(1366, 768);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QString error;
        QVERIFY2(w.openLink(device::LinkRequest::simulatedHipnuc(sim::SimOptions{}, 0), &error), qPrintable(error));
        w.newWorkspace();
        QVERIFY2(w.connectSimulated(ui::PortChoice::simulated(QStringLiteral("HEC495"), QString()), 0, &error),
                 qPrintable(error));
        QCOMPARE(w.workspaceCount(), 2);
        ui::DeviceWorkspace *hi14 = w.workspace(0), *hec = w.workspace(1);
        QTRY_VERIFY_WITH_TIMEOUT(hi14->state() == device::SessionState::Connected, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(hec->state() == device::SessionState::Connected, 15000);

        // The Time sync panel: the HI14's HI91 counter aligned after a few seconds of data.
        QVERIFY(hi14->syncDock());
        const auto *clocks = hi14->clockModel();
        QTRY_VERIFY_WITH_TIMEOUT(clocks->rowCount() >= 1, 5000);
        const QModelIndex state = clocks->index(0, models::ClockStatsModel::StateColumn);
        QTRY_COMPARE_WITH_TIMEOUT(clocks->data(state, models::ClockStatsModel::StateRole).toString(),
                                  QStringLiteral("aligned"), 10000);
        QCOMPARE(clocks->data(clocks->index(0, models::ClockStatsModel::StreamColumn)).toString(), QStringLiteral("HI91"));
        QVERIFY(!clocks->data(clocks->index(0, models::ClockStatsModel::DriftColumn)).toString().isEmpty());

        // Device > Record all devices.
        QTemporaryDir dir;
        QAction *recordAll = w.findChild<QAction *>(QStringLiteral("recordAllAction"));
        QVERIFY(recordAll && recordAll->isEnabled());
        recordAll->trigger();
        auto *win = w.findChild<ui::SessionRecordingWindow *>();
        QVERIFY(win && win->isVisible());
        win->setParentFolder(dir.path());
        win->start();
        QVERIFY2(win->isRecording(), qPrintable(win->findChild<QLabel *>(QStringLiteral("sessionStatus"))->text()));
        auto *table = win->findChild<QTableWidget *>(QStringLiteral("sessionDevices"));
        QCOMPARE(table->rowCount(), 2);
        // Three seconds' worth of the HI14 (100 Hz) and some answers of the compass in the files.
        QTRY_VERIFY_WITH_TIMEOUT(win->group()->manifest().devices[0].frames > 300
                                     && win->group()->manifest().devices[1].frames > 15,
                                 20000);
        QVERIFY(!win->findChild<QPushButton *>(QStringLiteral("startSessionRecording"))->isEnabled());
        // Issue 53: each tab's Recording panel shows this session's folder and its device's file,
        // not the default folder and the file name's template, and its clock runs.
        const QString sessionFolder = win->group()->folder();
        for (ui::DeviceWorkspace *ws : {hi14, hec}) {
            auto *panel = ws->recordingControls();
            QTRY_VERIFY(panel->isRecording());
            const QString shownFolder = panel->findChild<QLineEdit *>(QStringLiteral("folder"))->text();
            const QString shownFile = panel->findChild<QLineEdit *>(QStringLiteral("pattern"))->text();
            QCOMPARE(QDir::cleanPath(QDir::fromNativeSeparators(shownFolder)), QDir::cleanPath(sessionFolder));
            QVERIFY2(!shownFile.contains(QLatin1Char('{')) && QFileInfo::exists(QDir(sessionFolder).filePath(shownFile)),
                     qPrintable(shownFile));
            QCOMPARE(QDir(shownFolder).filePath(shownFile), panel->currentPath());
        }
        auto *elapsed = hi14->recordingControls()->findChild<QLabel *>(QStringLiteral("elapsed"));
        QTRY_VERIFY_WITH_TIMEOUT(elapsed->text() != QStringLiteral("00:00:00"), 5000);
        QSignalSpy finished(win, &ui::SessionRecordingWindow::recordingFinished);
        win->stop();
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        QVERIFY(finished.at(0).at(1).toBool());
        // Stopped: the panel's own folder and file name template are back.
        QTRY_VERIFY(!hi14->recordingControls()->isRecording());
        QVERIFY(hi14->recordingControls()->findChild<QLineEdit *>(QStringLiteral("pattern"))->text().contains(QLatin1Char('{')));
        const QString folder = win->lastSession();
        record::SessionManifest m;
        QVERIFY2(record::SessionManifest::load(folder, &m, &error), qPrintable(error));
        QCOMPARE(int(m.devices.size()), 2);
        QCOMPARE(m.devices[0].linkKind, QStringLiteral("HiPNUC serial"));
        QCOMPARE(m.devices[1].linkKind, QStringLiteral("HEC495 serial"));
        QVERIFY2(m.devices[0].frames > 200, qPrintable(QString::number(m.devices[0].frames))); // 100 Hz for 3 s
        QVERIFY(m.devices[1].frames > 10);
        QVERIFY(!m.devices[0].clocks.empty());
        QCOMPARE(table->item(0, 4)->text(), QStringLiteral("complete"));
        if (const QString shots = qEnvironmentVariable("IMUDESK_TEST_SHOTS"); !shots.isEmpty())
            win->grab().save(QDir(shots).filePath(QStringLiteral("record-all.png"))); // to look at it

        // Export aligned: one CSV beside the folder, both devices in it.
        QSignalSpy exported(win, &ui::SessionRecordingWindow::exportFinished);
        auto *exportButton = win->findChild<QPushButton *>(QStringLiteral("exportSession"));
        QVERIFY(exportButton->isEnabled());
        exportButton->click();
        QTRY_COMPARE_WITH_TIMEOUT(exported.size(), 1, 20000);
        QVERIFY2(exported.at(0).at(0).toBool(), qPrintable(exported.at(0).at(1).toString()));
        QFile csv(folder + QStringLiteral(".csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QByteArray text = csv.readAll();
        QVERIFY(text.startsWith("device,time_s"));
        QVERIFY(text.count('\n') > 250);
        QVERIFY(errors.isEmpty());
        win->close();

        // The session replays in the window: File > Open capture on its session.json opens one
        // replay tab per device, on the session's timeline, and their controls move them together.
        QVERIFY(w.tools()->openCapture(QDir(folder).filePath(QStringLiteral("session.json"))));
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
        QCOMPARE(w.workspaceCount(), 4);
        std::vector<record::ReplaySession *> replays;
        std::vector<ui::ReplayControls *> controls;
        for (int i = 2; i < 4; ++i) {
            auto *replay = qobject_cast<record::ReplaySession *>(&w.workspace(i)->link());
            QVERIFY(replay && replay->group());
            replays.push_back(replay);
            controls.push_back(w.workspace(i)->findChild<ui::ReplayControls *>(QStringLiteral("replayControls")));
            QVERIFY(controls.back());
        }
        QCOMPARE(replays[0]->group(), replays[1]->group());
        QCOMPARE(int(replays[0]->group()->members().size()), 2);
        // Both open on the session's length (from its start to its stop), and play at once.
        QTRY_VERIFY_WITH_TIMEOUT(controls[0]->duration() > 2.5 && controls[1]->duration() > 2.5, 5000);
        QCOMPARE(controls[0]->duration(), controls[1]->duration());
        auto *linked = controls[1]->findChild<QLabel *>(QStringLiteral("linked"));
        QVERIFY(linked && linked->isVisibleTo(controls[1]));
        auto *speed = controls[1]->findChild<QComboBox *>(QStringLiteral("speed"));
        QCOMPARE(speed->findData(0.0), -1); // no common pace: not offered
        // Pause in one tab pauses both; seek in the other moves both.
        auto *play1 = controls[1]->findChild<QPushButton *>(QStringLiteral("play"));
        QTRY_COMPARE(play1->text(), QStringLiteral("Pause"));
        play1->click();
        auto *play0 = controls[0]->findChild<QPushButton *>(QStringLiteral("play"));
        QTRY_COMPARE(play0->text(), QStringLiteral("Play"));
        QTRY_COMPARE(play1->text(), QStringLiteral("Play"));
        replays[0]->seek(1.0);
        QTRY_COMPARE(controls[1]->position(), 1.0);
        QTRY_COMPARE(controls[0]->position(), 1.0);
        // Played from there, both devices' samples reach their tabs, the HiPNUC module's with
        // common times, from one second into the session on.
        const uint64_t from0 = replays[0]->store().totalAppended(), from1 = replays[1]->store().totalAppended();
        play0->click();
        QTRY_VERIFY_WITH_TIMEOUT(replays[0]->store().totalAppended() > from0 + 20 && replays[1]->store().totalAppended() > from1 + 2, 5000);
        QTRY_COMPARE(play1->text(), QStringLiteral("Pause"));
        play0->click();
        const auto hipnuc = replays[0]->store().since(from0);
        const auto compass = replays[1]->store().since(from1);
        QVERIFY(hipnuc.front().commonTimeNs != 0);
        const int64_t seekedTo = m.startedHostNs + 1'000'000'000;
        QVERIFY(hipnuc.front().hostTimeNs >= seekedTo && compass.front().hostTimeNs >= seekedTo);
        QVERIFY(hipnuc.front().hostTimeNs < seekedTo + 300'000'000 && compass.front().hostTimeNs < seekedTo + 300'000'000);
        if (const QString shots = qEnvironmentVariable("IMUDESK_TEST_SHOTS"); !shots.isEmpty())
            w.grab().save(QDir(shots).filePath(QStringLiteral("session-replay.png")));
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
    }
};

IMUDESK_TEST_MAIN(TstSessionRecording)
#include "tst_session_recording.moc"
