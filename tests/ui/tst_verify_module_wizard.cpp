// Calibrate > Verify module… (issue 55), offscreen: the pose tiles fill as a hand-turned module
// (the verify rig) holds its poses, the result page shows every figure with its bound and
// verdict, a wrong module fails on its heading, the run is kept in the calibration history,
// and against the simulated module on a pseudo-terminal (Motion::Poses) the live tally counts
// the first poses. The two pages fit at 1366x768 in English and Chinese.
#include "calib/calibration_history.h"
#include "calibration/verify_module_wizard.h"
#include "device/device_session.h"
#include "sim/pty_simulator.h"
#include "workspace/language_switcher.h"
#include "../common/layout_checks.h"
#include "../common/test_main.h"
#include "../common/verify_rig.h"

#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QTest>

using namespace imudesk;


class TstVerifyModuleWizard : public QObject {
    Q_OBJECT

    std::unique_ptr<sim::PtySimulator> m_sim;
    std::unique_ptr<device::DeviceSession> m_session;

    void connectSession(sim::Motion motion)
    {
        m_session.reset();
        sim::SimOptions o;
        o.motion = motion;
        o.seed = 81;
        m_sim = std::make_unique<sim::PtySimulator>(o);
        QVERIFY(m_sim->start());
        m_session = std::make_unique<device::DeviceSession>();
        m_session->open(m_sim->devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(m_session->state(), device::SessionState::Connected, 15000);
    }

    // Runs a recorded module through the wizard's pages; returns the result page's verdict word.
    void runThrough(ui::VerifyModuleWizard &wizard, const test::HandTurnedModule &module, bool english = true)
    {
        // The recording as if the module had been turned while the wizard recorded (without
        // Start: the session's own static module would add its samples).
        wizard.show();
        wizard.addSamples(module.hi91Samples());
        for (bool done : wizard.tiles()->done())
            QVERIFY(done); // every tile: the rig turns through the twelve
        if (english)
            QVERIFY2(wizard.tallyLabel()->text().contains(QLatin1String("12 distinct poses")),
                     qPrintable(wizard.tallyLabel()->text()));
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::VerifyModuleWizard::ResultPage));
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void goodModulePassesAndIsKept()
    {
        connectSession(sim::Motion::Static);
        QTemporaryDir history;
        ui::VerifyModuleWizard wizard(*m_session);
        wizard.runSaver().setRoot(history.path());
        model::DeviceIdentity id;
        id.serial = "SIM-VERIFY-1";
        wizard.runSaver().setIdentity(id);
        // The simulator's gravity is the module's 1 G.
        wizard.findChild<QCheckBox *>()->setChecked(true);
        wizard.findChild<QDoubleSpinBox *>(QStringLiteral("verifyGravity"))->setValue(9.8);
        test::HandTurnedModule module;
        module.seed = 82;
        runThrough(wizard, module);
        QVERIFY2(wizard.report().verdict == verify::Verdict::Pass, qPrintable(wizard.report().reasons.join(QLatin1Char('\n'))));
        QVERIFY(wizard.verdictLabel()->text().contains(QLatin1String("pass")));
        QTableWidget *t = wizard.figureTable();
        QCOMPARE(t->rowCount(), 11);
        for (int r = 0; r < t->rowCount(); ++r)
            QVERIFY2(t->item(r, 4)->text() == QLatin1String("pass"),
                     qPrintable(t->item(r, 0)->text() + QLatin1String(": ") + t->item(r, 4)->text()));
        const calib::CalibrationHistory h(history.path());
        const auto runs = h.list(QStringLiteral("SIM-VERIFY-1"));
        QCOMPARE(runs.size(), 1);
        QCOMPARE(runs[0].kind, QStringLiteral("verify"));
        QCOMPARE(runs[0].verdict(), QStringLiteral("pass"));
        QCOMPARE(runs[0].result.value(QStringLiteral("poses")).toInt(), 12);
        calib::SampleTable samples;
        QString error;
        QVERIFY2(h.loadSamples(runs[0], samples, &error), qPrintable(error));
        QVERIFY(samples.rows.size() > 10000);
        // The gravity is remembered for the next run.
        ui::VerifyModuleWizard again(*m_session);
        QVERIFY(again.findChild<QCheckBox *>()->isChecked());
        QCOMPARE(again.options().gravityMs2, 9.8);
    }

    void headingBiasFails()
    {
        connectSession(sim::Motion::Static);
        QTemporaryDir history;
        ui::VerifyModuleWizard wizard(*m_session);
        wizard.runSaver().setRoot(history.path());
        test::HandTurnedModule module;
        module.seed = 83;
        module.attitudeBiasDeg = {0, 0, 3};
        runThrough(wizard, module);
        QCOMPARE(wizard.report().verdict, verify::Verdict::Fail);
        QTableWidget *t = wizard.figureTable();
        QCOMPARE(t->item(8, 0)->text(), QStringLiteral("Heading error (°)"));
        QCOMPARE(t->item(8, 4)->text(), QStringLiteral("fail"));
        QVERIFY(std::fabs(t->item(8, 1)->text().toDouble() - 3.0) < 0.3);
    }

    // The live tally against the simulated module turned by hand: the first pose lights its
    // tile and the countdown runs while it is held.
    void liveTallyCountsPoses()
    {
        connectSession(sim::Motion::Poses);
        ui::VerifyModuleWizard wizard(*m_session);
        wizard.show();
        QTest::mouseClick(wizard.startButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(wizard.holdLabel()->text().startsWith(QLatin1String("Hold still")), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(std::count(wizard.tiles()->done().begin(), wizard.tiles()->done().end(), true) >= 1, 15000);
        QVERIFY(!wizard.tallyLabel()->text().startsWith(QLatin1String("0 distinct")));
        // Next without enough poses: the result page says what cannot be judged.
        wizard.next();
        QCOMPARE(wizard.currentId(), int(ui::VerifyModuleWizard::ResultPage));
        QCOMPARE(wizard.report().verdict, verify::Verdict::CannotJudge);
        QVERIFY(wizard.figureTable()->item(0, 1)->text().contains(QLatin1String("9 needed")));
    }

    void fitsAt1366x768_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void fitsAt1366x768()
    {
        QFETCH(QString, language);
        ui::LanguageSwitcher switcher;
        QString error;
        QVERIFY2(switcher.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        connectSession(sim::Motion::Static);
        ui::VerifyModuleWizard wizard(*m_session);
        wizard.setGeometry(QRect(QPoint(0, 0), QSize(1366, 768)).adjusted(20, 20, -20, -60));
        test::HandTurnedModule module;
        module.seed = 84;
        runThrough(wizard, module, language == QLatin1String("en"));
        QVERIFY(test::layout::layoutSettled(wizard));
        QStringList problems = test::layout::cutOrOutside(wizard);
        // IMUDESK_LAYOUT_SHOTS=DIR: both pages as PNGs there.
        const QString shots = qEnvironmentVariable("IMUDESK_LAYOUT_SHOTS");
        if (!shots.isEmpty())
            wizard.grab().save(QDir(shots).filePath(QStringLiteral("verify-result-1366x768-%1.png").arg(language)));
        wizard.back();
        QVERIFY(test::layout::layoutSettled(wizard));
        problems << test::layout::cutOrOutside(wizard);
        if (!shots.isEmpty())
            wizard.grab().save(QDir(shots).filePath(QStringLiteral("verify-poses-1366x768-%1.png").arg(language)));
        QVERIFY(switcher.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void cleanupTestCase()
    {
        m_session.reset();
        m_sim.reset();
    }
};

IMUDESK_TEST_MAIN(TstVerifyModuleWizard)
#include "tst_verify_module_wizard.moc"
