// The gyro scale wizard (offscreen) against the simulated module on a pseudo-terminal,
// turned by the simulator's turntable as a person would (two turns clockwise from t = 3 s,
// 0.5 % gyro scale error): Start (CONFIG USRCAL START 720), the live angle, Stop when the
// turn is done (CONFIG USRCAL STOP -> OK), and the result with our own estimate, kept in the
// calibration history with its samples (an ERR run too, as a failed run).
#include "../common/connected_session.h"
#include "../common/test_main.h"
#include "calib/calibration_history.h"
#include "device/device_session.h"
#include "calibration/gyro_scale_wizard.h"
#include "sim/pty_simulator.h"
#include "calibration/turn_gauge.h"

#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace imudesk;

class TstGyroScaleWizard : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // Runs go to the temporary history each test sets; nothing reaches the user's folder.
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // The preparation page reads what the module streams and offers to turn HI91 on only
    // when the gyroscope data is missing.
    void turnGaugeLapsAndWindow()
    {
        ui::TurnGauge gauge;
        gauge.resize(300, 300);
        gauge.setTarget(720, 5);
        QCOMPARE(gauge.lapDeg(), 0.0);
        QVERIFY(!gauge.inStopWindow());
        gauge.setProgress(412.0, -35.0);
        QCOMPARE(gauge.lapDeg(), 52.0);
        QCOMPARE(gauge.centreText(), QStringLiteral("412° of 720°"));
        QCOMPARE(gauge.detailText(), QStringLiteral("lap 2 of 2 · 35 deg/s"));
        QVERIFY(!gauge.inStopWindow());
        gauge.setProgress(716.0, 0.0);
        QVERIFY(gauge.inStopWindow());
        gauge.setProgress(726.0, 0.0);
        QVERIFY(!gauge.inStopWindow()); // overshot the window
        gauge.setProgress(720.0, 0.0);
        QCOMPARE(gauge.lapDeg(), 360.0);
        // Painted: the turned arc's colour is on the ring's first quarter (clockwise from the top).
        gauge.setProgress(300.0, 40.0);
        const QImage image = gauge.grab().toImage();
        const QPoint onRing(gauge.width() / 2 + int(0.6 * gauge.width() / 2 * std::sin(M_PI / 4)),
                            gauge.height() / 2 - int(0.6 * gauge.width() / 2 * std::cos(M_PI / 4)));
        const QColor blue(0x1f, 0x77, 0xb4);
        int hits = 0;
        for (int dy = -30; dy <= 30; ++dy)
            for (int dx = -30; dx <= 30; ++dx)
                hits += QColor(image.pixel(onRing + QPoint(dx, dy))) == blue;
        QVERIFY2(hits > 20, qPrintable(QString::number(hits)));
        gauge.clear();
        QCOMPARE(gauge.angle(), 0.0);
    }

    void preparationChecksTheStream()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Static;
        sim::PtySimulator simulator(o);
        device::DeviceSession session;
        testing::connectSession(simulator, session);
        if (QTest::currentTestFailed())
            return;
        ui::GyroScaleWizard wizard(session);
        wizard.show();
        // Streaming (the simulator's HI91 at 100 Hz): nothing to change.
        QTRY_VERIFY_WITH_TIMEOUT(wizard.gyroRateHz() >= ui::GyroScaleWizard::kMinGyroRateHz, 5000);
        QVERIFY(wizard.enableOutputButton()->isHidden());
        QVERIFY(wizard.streamStatusLabel()->text().contains(QStringLiteral("Ready")));
        // Output off: the page says so and offers the one command that brings it back.
        session.sendText(QStringLiteral("LOG HI91 ONTIME 0"));
        QTRY_VERIFY_WITH_TIMEOUT(wizard.gyroRateHz() == 0.0, 6000);
        QVERIFY(wizard.enableOutputButton()->isVisible() && wizard.enableOutputButton()->isEnabled());
        QVERIFY(wizard.streamStatusLabel()->text().contains(QStringLiteral("No gyroscope data")));
        QTest::mouseClick(wizard.enableOutputButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(wizard.gyroRateHz() >= ui::GyroScaleWizard::kMinGyroRateHz, 6000);
        QVERIFY(wizard.enableOutputButton()->isHidden());
        // The check runs only on the preparation page.
        wizard.next();
        const double rate = wizard.gyroRateHz();
        QTest::qWait(2 * ui::GyroScaleWizard::kStreamCheckMs); // duration under test: two check periods off the page
        QCOMPARE(wizard.gyroRateHz(), rate);
    }

    void runsAgainstTheSimulator()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Turntable;
        o.gyroScaleError = 0.005;
        o.seed = 12;
        sim::PtySimulator simulator(o);
        device::DeviceSession session;
        testing::connectSession(simulator, session);
        if (QTest::currentTestFailed())
            return;

        QTemporaryDir history;
        ui::GyroScaleWizard wizard(session);
        wizard.runSaver().setRoot(history.path());
        model::DeviceIdentity id;
        id.productName = "HI14R3";
        id.serial = "SIM-GYRO-1";
        id.firmware = model::FirmwareVersion{1, 7, 1};
        wizard.runSaver().setIdentity(id);
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
        // The gauge shows the same turn: two laps, inside the stop window.
        QTRY_VERIFY(std::fabs(wizard.gauge()->angle() - std::fabs(wizard.run().result().legs.front().angleDeg)) < 1.0);
        QVERIFY(wizard.gauge()->inStopWindow());
        QTest::mouseClick(wizard.stopButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(wizard.deviceCalibration().state(), calib::GyroCalSession::State::Succeeded, 5000);
        QTRY_VERIFY(wizard.button(QWizard::NextButton)->isEnabled());
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::GyroScaleWizard::ResultPage));
        QVERIFY(wizard.resultText().contains(QStringLiteral("OK")));
        const double est = wizard.run().result().scaleErrorPct;
        QVERIFY2(std::fabs(est - 0.5) < 0.1, qPrintable(QString::number(est)));
        // The run is in the history: target, the device's reply, our estimate, the samples.
        QVERIFY2(wizard.runSaver().saved(), qPrintable(wizard.runSaver().lastError()));
        const calib::CalibrationHistory h(history.path());
        const auto runs = h.list(QStringLiteral("SIM-GYRO-1"));
        QCOMPARE(runs.size(), 1);
        QCOMPARE(runs[0].kind, QStringLiteral("gyro_scale"));
        QCOMPARE(runs[0].product, QStringLiteral("HI14R3"));
        QCOMPARE(runs[0].firmware, QStringLiteral("1.7.1"));
        QCOMPARE(runs[0].result.value(QStringLiteral("target_deg")).toInt(), 720);
        QVERIFY(runs[0].result.value(QStringLiteral("device_ok")).toBool());
        QCOMPARE(runs[0].result.value(QStringLiteral("scale_error_pct")).toDouble(), est);
        QVERIFY(!runs[0].verdict().isEmpty() && runs[0].verdict() != QStringLiteral("fail"));
        calib::SampleTable samples;
        QVERIFY(h.loadSamples(runs[0], samples));
        QVERIFY(samples.rows.size() > 500); // 20 s at the simulator's rate
        QCOMPARE(int(samples.rows.size()), runs[0].sampleCount);
        QVERIFY(samples.columnIndex(QStringLiteral("gyr_z")) >= 0);
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
        QTemporaryDir history;
        ui::GyroScaleWizard wizard(session);
        wizard.runSaver().setRoot(history.path());
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
        // Kept as a failed run (no identity: the "unknown" device).
        const auto runs = calib::CalibrationHistory(history.path()).list(QString());
        QCOMPARE(runs.size(), 1);
        QCOMPARE(runs[0].verdict(), QStringLiteral("fail"));
    }
};

IMUDESK_TEST_MAIN(TstGyroScaleWizard)
#include "tst_gyro_scale_wizard.moc"
