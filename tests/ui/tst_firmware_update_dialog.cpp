// The firmware update dialog, offscreen, against the simulated module on a pty: file
// information, a refused file, progress to the new version, cancel and finishing later.
#include "../common/ui_families.h"
#include "../common/firmware_files.h"
#include "../common/test_main.h"
#include "workspace/device_workspace.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "workspace/main_window.h"
#include "bridge/live_bridge_dialog.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "sim/kboot_bootloader.h"
#include "sim/pty_simulator.h"

#include <QAction>
#include <QLabel>
#include <QStandardPaths>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;
using ui::FirmwareUpdateDialog;

namespace {

constexpr int kBaud = 921600;

protocol::ihex::FirmwareImage image(const std::string &version, size_t size)
{
    return imudesk::test::appImage(version, size, 5);
}

using imudesk::test::writeFile;

bool flashHolds(sim::PtySimulator &s, const protocol::ihex::FirmwareImage &img)
{
    bool same = false;
    s.withDevice([&](sim::HipnucSimulator &d) {
        same = std::equal(img.data.begin(), img.data.end(), d.bootloader().flash().begin() + img.startAddress);
    });
    return same;
}

// Device > Update firmware with the demo image, as a user does: the dialog takes the tab's
// port, the update runs, the dialog is closed and the tab connects again, at the new version.
void updateFromTheMenu(ui::MainWindow &w, ui::DeviceWorkspace *ws)
{
    auto *action = w.findChild<QAction *>(QStringLiteral("firmwareAction"));
    QTRY_VERIFY_WITH_TIMEOUT(ws->state() == device::SessionState::Connected && ws->identity()
                                 && ws->identity()->firmware && action->isEnabled(),
                             15000);
    action->trigger();
    auto *dlg = w.findChild<FirmwareUpdateDialog *>();
    QVERIFY(dlg);
    dlg->findChild<QPushButton *>(QStringLiteral("demoImage"))->click();
    QSignalSpy finished(dlg, &FirmwareUpdateDialog::updateFinished);
    QVERIFY(dlg->startUpdate()); // at once, as a user may: the tab's link may still be closing
    QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 60000);
    QVERIFY2(finished.at(0).at(0).toBool(),
             qPrintable(dlg->findChild<QLabel *>(QStringLiteral("outcome"))->text()));
    dlg->close();
    QTRY_VERIFY(!w.findChild<FirmwareUpdateDialog *>());
    QTRY_VERIFY_WITH_TIMEOUT(ws->state() == device::SessionState::Connected && ws->identity()
                                 && ws->identity()->firmware && ws->identity()->firmware->toString() == "1.7.2",
                             20000);
}

quint16 freeTcpPort()
{
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}

} // namespace

class TstFirmwareUpdateDialog : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void refusedFile()
    {
        FirmwareUpdateDialog dlg(QStringLiteral("/dev/null"), kBaud, std::nullopt);
        const QString bad = writeFile(m_dir, QStringLiteral("bad.hex"), ":0200000401\r\n");
        QVERIFY(!dlg.loadFile(bad));
        QVERIFY(dlg.findChild<QLabel *>(QStringLiteral("imageInfo"))->text().contains(QStringLiteral("line 1")));
        QVERIFY(!dlg.findChild<QPushButton *>(QStringLiteral("start"))->isEnabled());
        QVERIFY(!dlg.startUpdate());
    }

    void updatesToTheNewVersion()
    {
        sim::PtySimulator s([] {
            sim::SimOptions o;
            o.baud = kBaud;
            return o;
        }());
        QVERIFY(s.start());
        model::DeviceIdentity id;
        id.productName = "HI14R3";
        id.firmware = model::FirmwareVersion{1, 7, 1};
        FirmwareUpdateDialog dlg(s.devicePath(), kBaud, id);
        dlg.show();
        QVERIFY(dlg.findChild<QLabel *>(QStringLiteral("versions"))->text().contains(QStringLiteral("1.7.1")));
        const auto img = image("1.7.2", 24 * 1024);
        QVERIFY(dlg.loadFile(writeFile(m_dir, QStringLiteral("fw.hex"), protocol::ihex::IntelHexWriter::write(img))));
        const QString info = dlg.findChild<QLabel *>(QStringLiteral("imageInfo"))->text();
        QVERIFY2(info.contains(QStringLiteral("24576 bytes from 0x00008000")), qPrintable(info));
        QVERIFY2(info.contains(QStringLiteral("CRC-32 0x")), qPrintable(info));
        QSignalSpy finished(&dlg, &FirmwareUpdateDialog::updateFinished);
        QTest::mouseClick(dlg.findChild<QPushButton *>(QStringLiteral("start")), Qt::LeftButton);
        QVERIFY(dlg.isRunning());
        QCOMPARE(dlg.findChild<QPushButton *>(QStringLiteral("cancel"))->text(), QStringLiteral("Cancel"));
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 30000);
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(dlg.findChild<QLabel *>(QStringLiteral("versions"))->text().contains(QStringLiteral("1.7.2 (new)")));
        QCOMPARE(dlg.findChild<QProgressBar *>(QStringLiteral("progress"))->value(), 1000);
        QVERIFY(dlg.findChild<QLabel *>(QStringLiteral("rate"))->text().contains(QStringLiteral("bytes/s")));
        QVERIFY(dlg.findChild<QPlainTextEdit *>(QStringLiteral("log"))->toPlainText().contains(QStringLiteral("verified")));
        QVERIFY(dlg.findChild<QLabel *>(QStringLiteral("outcome"))->text().startsWith(QStringLiteral("Done")));
        QCOMPARE(dlg.result().verifyMethod, QStringLiteral("read-back"));
        QVERIFY(flashHolds(s, img));
    }

    // The README's demo reaches the update: Device > Update firmware on the simulated HI14 is
    // enabled, the dialog offers a demo image, the simulated bootloader takes it, and the tab
    // connects again to the module, which now reports the new firmware.
    void demoDeviceUpdatesFromTheMenu()
    {
        QStandardPaths::setTestModeEnabled(true);
        ui::MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &m) { QFAIL(qPrintable(m)); });
        w.show();
        sim::SimOptions o;
        o.motion = sim::Motion::Static;
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(o, 0), &error), qPrintable(error));
        ui::DeviceWorkspace *ws = w.currentWorkspace();
        auto *action = w.findChild<QAction *>(QStringLiteral("firmwareAction"));
        QTRY_VERIFY_WITH_TIMEOUT(ws->identity() && ws->identity()->firmware && action->isEnabled(), 15000);
        const QString before = QString::fromStdString(ws->identity()->firmware->toString());
        action->trigger();
        auto *dlg = w.findChild<FirmwareUpdateDialog *>();
        QVERIFY(dlg);
        auto *demo = dlg->findChild<QPushButton *>(QStringLiteral("demoImage"));
        QVERIFY(demo && !demo->isHidden());
        demo->click(); // as the user does
        QVERIFY(!dlg->findChild<QLineEdit *>(QStringLiteral("file"))->text().isEmpty());
        QVERIFY(dlg->findChild<QLineEdit *>(QStringLiteral("file"))->text().contains(QStringLiteral("1.7.2")));
        const QString info = dlg->findChild<QLabel *>(QStringLiteral("imageInfo"))->text();
        QVERIFY2(info.contains(QStringLiteral("CRC-32")), qPrintable(info));
        QVERIFY(ws->isSimulated()); // the module keeps running while the dialog has its port
        QTRY_VERIFY_WITH_TIMEOUT(ws->state() == device::SessionState::Closed, 5000);
        QSignalSpy finished(dlg, &FirmwareUpdateDialog::updateFinished);
        QVERIFY(dlg->startUpdate());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 60000);
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dlg->findChild<QLabel *>(QStringLiteral("outcome"))->text()));
        dlg->close();
        // The tab takes the port back and reads the new version.
        QTRY_VERIFY_WITH_TIMEOUT(ws->state() == device::SessionState::Connected && ws->identity()
                                     && ws->identity()->firmware
                                     && ws->identity()->firmware->toString() == "1.7.2",
                                 20000);
        QVERIFY(before != QStringLiteral("1.7.2"));
        w.disconnectDevice();
    }

    // Issue 53: the demo's update worked once, then said "nothing answered" (and the tab
    // complained of bytes that form no frame): twice in a row with the live bridge running,
    // as the demo's user did, then on a second tab's fresh simulated module.
    void demoUpdatesTwiceWithTheBridgeAndOnASecondTab()
    {
        QStandardPaths::setTestModeEnabled(true);
        ui::MainWindow w(imudesk::test::builtInFamilies());
        QStringList errors;
        w.setErrorPresenter([&errors](const QString &m) { errors << m; });
        w.show();
        sim::SimOptions o; // as the demo: HI14, firmware 1.7.1, HI91 at 100 Hz, tumbling, rate detected
        o.motion = sim::Motion::Tumble;
        QString error;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(o, 0), &error), qPrintable(error));
        ui::DeviceWorkspace *first = w.currentWorkspace();
        QTRY_COMPARE_WITH_TIMEOUT(first->state(), device::SessionState::Connected, 15000);
        ui::LiveBridgeDialog *bridge = w.openLiveBridge();
        bridge->findChild<QSpinBox *>(QStringLiteral("bridgePort"))->setValue(freeTcpPort());
        QVERIFY2(bridge->startBridge(), qPrintable(bridge->lastError()));
        bridge->close(); // the bridge runs on
        updateFromTheMenu(w, first);
        if (QTest::currentTestFailed())
            return;
        updateFromTheMenu(w, first);
        if (QTest::currentTestFailed())
            return;
        QVERIFY2(w.openLink(imudesk::device::LinkRequest::simulatedHipnuc(o, 0), &error), qPrintable(error));
        ui::DeviceWorkspace *second = w.currentWorkspace();
        QVERIFY(second != first);
        updateFromTheMenu(w, second);
        if (QTest::currentTestFailed())
            return;
        QVERIFY2(errors.isEmpty(), qPrintable(errors.join(QLatin1Char('\n'))));
        QCOMPARE(first->state(), device::SessionState::Connected);
        w.disconnectDevice();
    }

    void cancelThenFinish()
    {
        sim::PtySimulator s([] {
            sim::SimOptions o;
            o.baud = kBaud;
            return o;
        }());
        QVERIFY(s.start());
        FirmwareUpdateDialog dlg(s.devicePath(), kBaud, std::nullopt);
        const auto img = image("1.7.3", 128 * 1024);
        QVERIFY(dlg.loadFile(writeFile(m_dir, QStringLiteral("fw2.hex"), protocol::ihex::IntelHexWriter::write(img))));
        QSignalSpy finished(&dlg, &FirmwareUpdateDialog::updateFinished);
        QVERIFY(dlg.startUpdate());
        auto *bar = dlg.findChild<QProgressBar *>(QStringLiteral("progress"));
        auto *state = dlg.findChild<QLabel *>(QStringLiteral("state"));
        QTRY_VERIFY_WITH_TIMEOUT(state->text() == QStringLiteral("writing") && bar->value() > 100, 20000);
        QTest::mouseClick(dlg.findChild<QPushButton *>(QStringLiteral("cancel")), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 20000);
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QCOMPARE(dlg.result().finalState, firmware::UpdateFlow::State::Cancelled);
        QVERIFY(dlg.findChild<QLabel *>(QStringLiteral("outcome"))->text().contains(QStringLiteral("run the update again")));
        QVERIFY(!flashHolds(s, img));
        QVERIFY(dlg.startUpdate());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 2, 60000);
        QCOMPARE(finished.at(1).at(0).toBool(), true);
        QVERIFY(dlg.result().resumed);
        QVERIFY(flashHolds(s, img));
    }
};

IMUDESK_TEST_MAIN(TstFirmwareUpdateDialog)
#include "tst_firmware_update_dialog.moc"
