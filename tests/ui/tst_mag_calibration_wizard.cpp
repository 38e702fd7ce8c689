// The magnetometer calibration wizard (offscreen) against the simulated module on a
// pseudo-terminal while it tumbles: every page in turn, the environment check, the
// rotation page collecting samples on the sphere with the device's MCAL run beside it
// (STAT=1 and PROGRESS), our fit and its verdict on the result page (kept in the calibration
// history with its samples), and the heading check.
#include "calib/calibration_history.h"
#include "calib/mag_calibrator.h"
#include "device/device_session.h"
#include "calibration/mag_calibration_wizard.h"
#include "calibration/mag_sphere_view.h"
#include "settings/configuration_controller.h"
#include "sim/pty_simulator.h"

#include <QPushButton>
#include <QLabel>
#include <QDir>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using namespace imudesk;

class TstMagCalibrationWizard : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void walksThroughAgainstTheSimulator()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Tumble;
        o.seed = 8;
        sim::PtySimulator simulator(o);
        QVERIFY(simulator.start());
        device::DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);

        QTemporaryDir history;
        ui::MagCalibrationWizard wizard(session, model::FirmwareVersion{1, 7, 1});
        wizard.runSaver().setRoot(history.path());
        model::DeviceIdentity id;
        id.productName = "HI14R3";
        id.serial = "SIM-MAG-1";
        id.firmware = model::FirmwareVersion{1, 7, 1};
        wizard.runSaver().setIdentity(id);
        wizard.show();
        QCOMPARE(wizard.currentId(), int(ui::MagCalibrationWizard::IntroPage));
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::MagCalibrationWizard::ModePage));
        // The mode is read first: the module already runs in 9-axis mode, so no switch is offered.
        QTRY_COMPARE_WITH_TIMEOUT(wizard.attMode(), QStringLiteral("1"), 10000);
        QVERIFY(wizard.switchModeButton()->isHidden());
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::MagCalibrationWizard::EnvironmentPage));
        // The simulator's field: |B| about 50 uT (28 horizontal, 42 down) plus its hard iron.
        QTRY_VERIFY_WITH_TIMEOUT(wizard.environment().count() >= 20, 5000);
        QVERIFY(wizard.environment().meanFieldUt() > 10);
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::MagCalibrationWizard::RotationPage));
        // A large sphere and the live figures.
        QVERIFY(std::min(wizard.sphere()->width(), wizard.sphere()->height()) >= 360);
        QVERIFY(wizard.liveFiguresText().contains(QStringLiteral("Largest gap")));
        QTest::mouseClick(wizard.startDeviceButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(wizard.deviceCalibration().procedure().progress() > 0, 10000);
        QCOMPARE(wizard.deviceCalibration().procedure().stat(), 1);
        QTRY_VERIFY_WITH_TIMEOUT(wizard.sphere()->sampleCount() > 300, 10000);
        QVERIFY(wizard.sphere()->coveragePercent() > 0);
        // Within a second or two the live fit has a verdict so far and figures from it.
        QTRY_VERIFY_WITH_TIMEOUT(!wizard.findChild<QLabel *>(QStringLiteral("liveVerdict"))->text().isEmpty(), 5000);
        QVERIFY(wizard.liveFiguresText().contains(QStringLiteral("Raw |B|")));
        QTest::mouseClick(wizard.fitButton(), Qt::LeftButton);
        QVERIFY(wizard.fitted());
        // The verdict as a headline, coloured by it.
        QVERIFY(wizard.verdictHeadline()->text().contains(calib::MagCalResult::verdictText(wizard.result().verdict)));
        QVERIFY(wizard.verdictHeadline()->styleSheet().contains(
            wizard.result().verdict == calib::MagVerdict::Pass ? QStringLiteral("#2e7d32")
            : wizard.result().verdict == calib::MagVerdict::Warn ? QStringLiteral("#e65100")
                                                                  : QStringLiteral("#c62828")));
        QVERIFY(wizard.result().samples >= 300); // the samples the sphere showed
        // A few seconds of tumbling cover only part of the sphere: the full fit is refused, honestly.
        QVERIFY(!wizard.resultText().isEmpty());
        if (wizard.result().verdict == calib::MagVerdict::Refused)
            QVERIFY(wizard.resultText().contains(QStringLiteral("20-60 uT")));
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::MagCalibrationWizard::ResultPage));
        // The run is kept: result with metrics and verdict, and the samples that were fitted.
        QVERIFY2(wizard.runSaver().saved(), qPrintable(wizard.runSaver().lastError()));
        const calib::CalibrationHistory h(history.path());
        const auto runs = h.list(QStringLiteral("SIM-MAG-1"));
        QCOMPARE(runs.size(), 1);
        QCOMPARE(runs[0].kind, QStringLiteral("magnetometer"));
        QCOMPARE(runs[0].verdict(), QLatin1String(calib::verdictName(wizard.result().verdict)));
        QCOMPARE(runs[0].result.value(QStringLiteral("reason")).toString(), wizard.result().reason);
        QVERIFY(runs[0].result.contains(QStringLiteral("coverage_pct")));
        calib::SampleTable samples;
        QVERIFY(h.loadSamples(runs[0], samples));
        QCOMPARE(int(samples.rows.size()), wizard.result().samples);
        std::vector<Eigen::Vector3d> mags;
        QVERIFY(calib::SampleCsv::magnetometer(samples, mags));
        QVERIFY(wizard.page(ui::MagCalibrationWizard::ResultPage)->findChildren<QLabel *>().size() >= 2);
        bool shown = false;
        for (const QLabel *l : wizard.page(ui::MagCalibrationWizard::ResultPage)->findChildren<QLabel *>())
            shown = shown || l->text().contains(QDir::toNativeSeparators(runs[0].folder));
        QVERIFY(shown); // the result page says where
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::MagCalibrationWizard::HeadingPage));
        QTRY_VERIFY_WITH_TIMEOUT(wizard.headingTurnedDeg() > 20, 5000);
        QVERIFY(wizard.headingMaxJumpDeg() < ui::MagCalibrationWizard::kMaxHeadingJumpDeg);
    }

    void offersTheSwitchOnlyInASixAxisMode()
    {
        sim::SimOptions o;
        o.motion = sim::Motion::Static;
        sim::PtySimulator simulator(o);
        QVERIFY(simulator.start());
        device::DeviceSession session;
        session.open(simulator.devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(session.state(), device::SessionState::Connected, 15000);
        // The module runs in the 6-axis mode (not saved).
        settings::ConfigurationController config(session);
        QSignalSpy read(&config, &settings::ConfigurationController::readFinished);
        config.readAll();
        QTRY_COMPARE_WITH_TIMEOUT(read.size(), 1, 10000);
        QSignalSpy applied(&config, &settings::ConfigurationController::applyFinished);
        config.apply({{QStringLiteral("ATT.MODE"), QStringLiteral("0")}});
        QTRY_COMPARE_WITH_TIMEOUT(applied.size(), 1, 10000);

        ui::MagCalibrationWizard wizard(session, model::FirmwareVersion{1, 7, 1});
        wizard.show();
        wizard.next();
        QTRY_COMPARE_WITH_TIMEOUT(wizard.attMode(), QStringLiteral("0"), 10000);
        QVERIFY(!wizard.switchModeButton()->isHidden());
        // The switch: ATT MODE 1, SAVECONFIG, REBOOT, then the mode is read back and the offer goes.
        QTest::mouseClick(wizard.switchModeButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(wizard.attMode(), QStringLiteral("1"), 20000);
        QVERIFY(wizard.switchModeButton()->isHidden());
    }
};

QTEST_MAIN(TstMagCalibrationWizard)
#include "tst_mag_calibration_wizard.moc"
