// The firmware update dialog's CAN link, offscreen, against the simulated HiPNUC CANopen module
// served in this process on Qt's virtualcan bus (its own TCP port): the link choice shows the CAN
// fields, the update reaches the new version verified by the bootloader's CRC, and a cancel
// mid-download leaves the module in its bootloader where a second update finishes.
#include "../common/ui_families.h"
#include "workspace/device_workspace.h"
#include "../common/firmware_files.h"
#include "../common/test_main.h"
#include "ui/firmware/firmware_update_dialog.h"
#include "workspace/main_window.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "sim/can_simulator.h"
#include "sim/kboot_bootloader.h"

#include <QCanBus>
#include <QAction>
#include <QComboBox>
#include <QLineEdit>
#include <QStandardPaths>
#include <QEventLoop>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <functional>

using namespace imudesk;
using ui::FirmwareUpdateDialog;

namespace {

const QString kInterface = QStringLiteral("tcp://127.0.0.1:24493/can0");

protocol::ihex::FirmwareImage image(const std::string &version, size_t size)
{
    return imudesk::test::appImage(version, size, 9);
}

using imudesk::test::writeFile;

// Runs the event loop (no sleeps: the simulator's bus server lives in this thread) until pred
// holds or timeoutMs passed.
bool spinUntil(const std::function<bool()> &pred, int timeoutMs)
{
    QEventLoop loop;
    QTimer check, limit;
    QObject::connect(&check, &QTimer::timeout, &loop, [&] {
        if (pred())
            loop.quit();
    });
    QObject::connect(&limit, &QTimer::timeout, &loop, &QEventLoop::quit);
    check.start(5);
    limit.start(timeoutMs);
    if (!pred())
        loop.exec();
    return pred();
}

bool flashHolds(sim::CanSimulator &s, const protocol::ihex::FirmwareImage &img)
{
    const auto area = s.device().bootloader().applicationArea();
    return std::equal(img.data.begin(), img.data.end(), area.begin());
}

sim::CanSimOptions canopen()
{
    sim::CanSimOptions o;
    o.protocol = protocol::can::CanProtocol::CanOpen;
    return o;
}

} // namespace

class TstFirmwareUpdateDialogCan : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void initTestCase()
    {
        if (!QCanBus::instance()->plugins().contains(QStringLiteral("virtualcan")))
            QSKIP("Qt's virtualcan CAN bus plugin is not installed (package libqt6serialbus6-plugins)");
    }

    void linkChoiceShowsCanFields()
    {
        FirmwareUpdateDialog dlg(QStringLiteral("/dev/ttyUSB0"), 115200, std::nullopt);
        dlg.show();
        auto *box = dlg.findChild<QGroupBox *>(QStringLiteral("canBox"));
        QVERIFY(box);
        QVERIFY(!box->isVisible());
        QCOMPARE(dlg.link(), FirmwareUpdateDialog::Link::Serial);
        dlg.setLink(FirmwareUpdateDialog::Link::Can);
        QVERIFY(box->isVisible());
        QVERIFY(dlg.findChild<QComboBox *>(QStringLiteral("canPlugin"))->findText(QStringLiteral("virtualcan")) >= 0);
        QVERIFY(!dlg.findChild<QSpinBox *>(QStringLiteral("canBitrate"))->toolTip().isEmpty());
        QCOMPARE(dlg.findChild<QSpinBox *>(QStringLiteral("canNode"))->value(), 8);
    }

    void updateThenCancelAndFinish()
    {
        sim::CanSimulator simulator(canopen());
        QString err;
        QVERIFY2(simulator.start(QStringLiteral("virtualcan"), kInterface, &err), qPrintable(err));
        FirmwareUpdateDialog dlg(QString(), 115200, std::nullopt);
        dlg.setLink(FirmwareUpdateDialog::Link::Can);
        dlg.setCanBus(QStringLiteral("virtualcan"), kInterface, 0, 8);
        const auto img = image("1.7.2", 2000);
        QVERIFY(dlg.loadFile(writeFile(m_dir, QStringLiteral("can.hex"), protocol::ihex::IntelHexWriter::write(img))));
        QSignalSpy finished(&dlg, &FirmwareUpdateDialog::updateFinished);
        QVERIFY(dlg.startUpdate());
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QCOMPARE(dlg.canResult().verifyMethod, QStringLiteral("bootloader CRC"));
        QVERIFY(flashHolds(simulator, img));
        QVERIFY2(dlg.findChild<QLabel *>(QStringLiteral("outcome"))->text().startsWith(QStringLiteral("Done")),
                 qPrintable(dlg.findChild<QLabel *>(QStringLiteral("outcome"))->text()));

        // Cancel mid-download (as the Cancel button does), then the second update finishes.
        const auto next = image("1.7.3", 8000);
        QVERIFY(dlg.loadFile(writeFile(m_dir, QStringLiteral("can2.hex"), protocol::ihex::IntelHexWriter::write(next))));
        auto *bar = dlg.findChild<QProgressBar *>(QStringLiteral("progress"));
        QVERIFY(dlg.startUpdate());
        QVERIFY(spinUntil([&] { return bar->value() > 100; }, 60000));
        dlg.findChild<QPushButton *>(QStringLiteral("cancel"))->click();
        QVERIFY(finished.wait(20000));
        QCOMPARE(finished.at(1).at(0).toBool(), false);
        QCOMPARE(dlg.canResult().finalState, firmware::CanUpdateFlow::State::Cancelled);
        QVERIFY(simulator.device().inBootloader());
        QVERIFY(dlg.startUpdate());
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.at(2).at(0).toBool(), true);
        QVERIFY(dlg.canResult().resumed);
        QVERIFY(flashHolds(simulator, next));
    }

    // Device > Update firmware on a workspace connected to a HiPNUC module over CANopen opens
    // the dialog on CAN, preset with the session's bus and node, and the update goes through.
    void deviceMenuOpensTheCanUpdate()
    {
        QStandardPaths::setTestModeEnabled(true);
        ui::MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &m) { QFAIL(qPrintable(m)); });
        w.show();
        ui::DeviceWorkspace *ws = w.freeWorkspaceForLink();
        device::CanSessionOptions o;
        o.plugin = QStringLiteral("virtualcan");
        o.interfaceName = kInterface; // virtualcan serves one port per process
        o.protocol = protocol::can::CanProtocol::CanOpen;
        o.node = 8;
        QString error;
        device::LinkRequest request = device::LinkRequest::canBus(o);
        request.simulate = true;
        QVERIFY2(w.openLink(request, &error), qPrintable(error));
        auto *action = w.findChild<QAction *>(QStringLiteral("firmwareAction"));
        QVERIFY(action);
        QVERIFY2(spinUntil([&] { return ws->state() == device::SessionState::Connected && action->isEnabled(); },
                          15000),
                 qPrintable(QStringLiteral("state %1, current %2, enabled %3")
                                .arg(int(ws->state()))
                                .arg(w.currentWorkspace() == ws)
                                .arg(action->isEnabled())));
        action->trigger();
        auto *dlg = w.findChild<FirmwareUpdateDialog *>();
        QVERIFY(dlg);
        QCOMPARE(dlg->link(), FirmwareUpdateDialog::Link::Can);
        QCOMPARE(dlg->findChild<QComboBox *>(QStringLiteral("canPlugin"))->currentText(), o.plugin);
        QCOMPARE(dlg->findChild<QLineEdit *>(QStringLiteral("canInterface"))->text(), o.interfaceName);
        QCOMPARE(dlg->findChild<QSpinBox *>(QStringLiteral("canNode"))->value(), 8);
        const auto img = image("1.7.4", 3000);
        QVERIFY(dlg->loadFile(writeFile(m_dir, QStringLiteral("menu.hex"), protocol::ihex::IntelHexWriter::write(img))));
        QSignalSpy finished(dlg, &FirmwareUpdateDialog::updateFinished);
        QVERIFY(dlg->startUpdate());
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QCOMPARE(dlg->canResult().verifyMethod, QStringLiteral("bootloader CRC"));
        dlg->close();
    }
};

IMUDESK_TEST_MAIN(TstFirmwareUpdateDialogCan)
#include "tst_firmware_update_dialog_can.moc"
