// The gyro scale wizard (offscreen) against the simulated module on a pseudo-terminal,
// turned by the simulator's turntable as a person would (two turns clockwise from t = 3 s,
// 0.5 % gyro scale error): Start (CONFIG USRCAL START 720), the live angle, Stop when the
// turn is done (CONFIG USRCAL STOP -> OK), and the result with our own estimate.
#include "device/device_session.h"
#include "gyro_scale_wizard.h"
#include "sim/pty_simulator.h"

#include <QPushButton>
#include <QSpinBox>
#include <QTest>

using namespace imudesk;

class TstGyroScaleWizard : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void runsAgainstTheSimulator()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Turntable;
        o.gyroScaleError = 0.005;
        o.seed = 12;
        sim::PtySimulator simulator(o);
        QString error;
        QVERIFY2(simulator.start(&error), qPrintable(error));
        device::DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);

        ui::GyroScaleWizard wizard(session);
        wizard.show();
        QCOMPARE(wizard.currentId(), int(ui::GyroScaleWizard::PreparePage));
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::GyroScaleWizard::RunPage));
        QVERIFY(!wizard.button(QWizard::NextButton)->isEnabled()); // not before the run ended
        wizard.angleBox()->setValue(720);
        QTest::mouseClick(wizard.startButton(), Qt::LeftButton);
        QTRY_COMPARE(wizard.deviceCalibration().state(), calib::GyroCalSession::State::Running);
        QVERIFY(wizard.stopButton()->isEnabled());
        // The turntable turns 720 deg and stops (about 20 s after the simulator started).
        QTRY_COMPARE_WITH_TIMEOUT(wizard.run().state(), calib::GyroScaleRun::State::Finished, 40000);
        QVERIFY(std::fabs(std::fabs(wizard.run().result().legs.front().angleDeg) - 720 * 1.005) < 2);
        QTest::mouseClick(wizard.stopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(wizard.deviceCalibration().state(), calib::GyroCalSession::State::Succeeded, 5000);
        QTRY_VERIFY(wizard.button(QWizard::NextButton)->isEnabled());
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::GyroScaleWizard::ResultPage));
        QVERIFY(wizard.resultText().contains(QStringLiteral("OK")));
        const double est = wizard.run().result().scaleErrorPct;
        QVERIFY2(std::fabs(est - 0.5) < 0.1, qPrintable(QString::number(est)));
        QVERIFY(!wizard.grab().isNull());
    }

    void refusesABadAngle()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Static;
        sim::PtySimulator simulator(o);
        QVERIFY(simulator.start());
        device::DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);
        ui::GyroScaleWizard wizard(session);
        // The spin box keeps the manual's range.
        wizard.angleBox()->setValue(100);
        QCOMPARE(wizard.angleBox()->value(), 720);
        wizard.angleBox()->setValue(5000);
        QCOMPARE(wizard.angleBox()->value(), 1800);
        // Stopping at once: the device answers ERR, the wizard says so.
        QTest::mouseClick(wizard.startButton(), Qt::LeftButton);
        QTRY_COMPARE(wizard.deviceCalibration().state(), calib::GyroCalSession::State::Running);
        QTest::mouseClick(wizard.stopButton(), Qt::LeftButton);
        QTRY_COMPARE(wizard.deviceCalibration().state(), calib::GyroCalSession::State::Failed);
        QVERIFY(wizard.resultText().contains(QStringLiteral("ERR")));
    }
};

QTEST_MAIN(TstGyroScaleWizard)
#include "tst_gyro_scale_wizard.moc"
