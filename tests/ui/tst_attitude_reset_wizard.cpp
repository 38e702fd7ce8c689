// The attitude reset wizard (offscreen) against the simulated module on a pseudo-terminal:
// the static module (roll 1.5, pitch -2.5 deg) is still and near level, so ATT RST 3 is
// sent after the stillness check and levels it; a spinning module is never still, so
// nothing is sent. The answered command is kept in the calibration history with its samples.
#include "calibration/attitude_reset_wizard.h"
#include "calib/calibration_history.h"
#include "device/device_session.h"
#include "sim/pty_simulator.h"
#include "../common/test_main.h"

#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;

namespace {
sim::SimOptions options(sim::Motion m)
{
    sim::SimOptions o;
    o.motion = m;
    o.seed = 21;
    return o;
}
} // namespace

class TstAttitudeResetWizard : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void levelsAStillModule()
    {
        sim::PtySimulator simulator(options(sim::Motion::Static));
        QVERIFY(simulator.start());
        device::DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);
        QTemporaryDir history;
        ui::AttitudeResetWizard wizard(session);
        wizard.runSaver().setRoot(history.path());
        model::DeviceIdentity id;
        id.serial = "SIM-ATT-1";
        wizard.runSaver().setIdentity(id);
        wizard.show();
        wizard.setVariant(3);
        QCOMPARE(wizard.variant(), 3);
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::AttitudeResetWizard::CheckPage));
        QVERIFY(!wizard.sendButton()->isEnabled()); // the stillness check comes first
        QVERIFY(!wizard.validateCurrentPage());
        QTRY_VERIFY_WITH_TIMEOUT(wizard.sendButton()->isEnabled(), 8000);
        QVERIFY(wizard.conditionsMet());
        QTest::mouseClick(wizard.sendButton(), Qt::LeftButton);
        QTRY_VERIFY(wizard.button(QWizard::NextButton)->isEnabled());
        QVERIFY(wizard.finishedOk());
        // The module reads level afterwards.
        QTRY_VERIFY_WITH_TIMEOUT(session.store().latest() && std::abs(session.store().latest()->pitch) < 0.3
                                     && std::abs(session.store().latest()->roll) < 0.3,
                                 3000);
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::AttitudeResetWizard::ResultPage));
        QVERIFY(wizard.resultText().contains(QStringLiteral("OK")));
        const calib::CalibrationHistory h(history.path());
        const auto runs = h.list(QStringLiteral("SIM-ATT-1"));
        QCOMPARE(runs.size(), 1);
        QCOMPARE(runs[0].kind, QStringLiteral("attitude_reset"));
        QCOMPARE(runs[0].verdict(), QStringLiteral("pass"));
        QCOMPARE(runs[0].result.value(QStringLiteral("variant")).toInt(), 3);
        QVERIFY(runs[0].result.value(QStringLiteral("still_for_s")).toDouble() >= ui::AttitudeResetWizard::kStillForS);
        calib::SampleTable samples;
        QVERIFY(h.loadSamples(runs[0], samples));
        QVERIFY(samples.rows.size() > 10);
    }

    void neverSendsWhileMoving()
    {
        sim::PtySimulator simulator(options(sim::Motion::Spin));
        QVERIFY(simulator.start());
        device::DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);
        QTemporaryDir history;
        ui::AttitudeResetWizard wizard(session);
        wizard.runSaver().setRoot(history.path());
        wizard.show();
        wizard.setVariant(1);
        wizard.next();
        QTest::qWait(3500); // duration under test: longer than the kStillForS (2 s) of stillness a send needs
        QVERIFY(!wizard.conditionsMet());
        QVERIFY(!wizard.sendButton()->isEnabled());
        QVERIFY(wizard.resultText().contains(QStringLiteral("Nothing")));
        QVERIFY(calib::CalibrationHistory(history.path()).devices().isEmpty()); // nothing sent, nothing kept
    }
};

IMUDESK_TEST_MAIN(TstAttitudeResetWizard)
#include "tst_attitude_reset_wizard.moc"
