// Hec495CalibrationWizard offscreen against the simulated HEC495 on a pseudo-terminal
// (HEC495 manual, "平面校准" and commands 2.8-2.11): a planar run on a compass the simulator
// turns level at 30 deg/s collects points (0x66), lights the targets it passes, saves
// (0x09) and shows the module's FitErr; a save with no valid point fails (89 FF) and says
// what to do; a closed connection says so. The manual method collects on "Collect point"
// (0x67), Stop (0x12) abandons the run and Clear (0x10) is accepted. A saved run is kept in
// the calibration history with FitErr, method and the attitude samples.
#include "calib/calibration_history.h"
#include "attitude/compass_pose_view.h"
#include "device/hec495_result.h"
#include "device/hec495_session.h"
#include "calibration/hec495_calibration_wizard.h"
#include "sim/hec495_simulator.h"
#include "sim/pty_simulator.h"
#include "../common/test_main.h"

#include <QPushButton>
#include <QSignalSpy>
#include <QDir>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <memory>

using namespace imudesk;
using namespace imudesk::sim;
using imudesk::calib::CompassCalMethod;
using imudesk::device::Hec495Result;
using imudesk::device::Hec495Session;
using imudesk::ui::Hec495CalibrationWizard;

namespace {

void withSim(PtySimulator &pty, const std::function<void(Hec495Simulator &)> &fn)
{
    pty.withSerialDevice([&fn](SimulatedSerialDevice &d) { fn(dynamic_cast<Hec495Simulator &>(d)); });
}

} // namespace

class TstHec495CalibrationWizard : public QObject {
    Q_OBJECT
    std::unique_ptr<PtySimulator> m_pty;
    std::unique_ptr<Hec495Session> m_session;

    void serve(Motion motion)
    {
        Hec495Options o;
        o.baud = 115200;
        o.motion = motion;
        m_pty = std::make_unique<PtySimulator>(std::make_unique<Hec495Simulator>(o));
        QVERIFY(m_pty->start());
        m_session = std::make_unique<Hec495Session>();
        m_session->open(m_pty->devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(m_session->state(), device::SessionState::Connected, 5000);
    }

    // Clicks a button of the wizard and waits for the result of its request.
    static Hec495Result click(Hec495CalibrationWizard &w, QPushButton *button)
    {
        QSignalSpy done(&w, &Hec495CalibrationWizard::requestFinished);
        if (!button->isEnabled())
            qFatal("%s is disabled", qPrintable(button->text()));
        button->click();
        if (!done.wait(5000))
            qFatal("no result for %s", qPrintable(button->text()));
        return done.at(0).at(0).value<Hec495Result>();
    }

    static void toRunPage(Hec495CalibrationWizard &w, CompassCalMethod m)
    {
        w.show();
        QCOMPARE(w.currentId(), int(Hec495CalibrationWizard::MethodPage));
        w.setMethod(m);
        w.next();
        QCOMPARE(w.currentId(), int(Hec495CalibrationWizard::RunPage));
        QCOMPARE(w.method(), m);
    }

private Q_SLOTS:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void cleanup()
    {
        m_session.reset();
        m_pty.reset();
    }

    void methods_data()
    {
        QTest::addColumn<int>("method");
        QTest::addColumn<int>("targets");
        QTest::addColumn<bool>("collectVisible");
        // HEC495 manual: tables of the 12-point methods, planar "最多采集 12 个点", no table
        // for manual and all-orientation.
        QTest::newRow("auto12") << int(CompassCalMethod::Auto12) << 12 << false;
        QTest::newRow("manual") << int(CompassCalMethod::Manual) << 0 << true;
        QTest::newRow("all-orientation") << int(CompassCalMethod::AutoAllOrientation) << 0 << false;
        QTest::newRow("small-tilt") << int(CompassCalMethod::Auto12SmallTilt) << 12 << false;
        QTest::newRow("planar") << int(CompassCalMethod::Planar) << 12 << false;
    }
    void methods()
    {
        QFETCH(int, method);
        QFETCH(int, targets);
        QFETCH(bool, collectVisible);
        serve(Motion::Static);
        Hec495CalibrationWizard w(*m_session);
        toRunPage(w, CompassCalMethod(method));
        QCOMPARE(int(w.tracker().poseTargets().size()), targets);
        QCOMPARE(w.collectButton()->isVisibleTo(&w), collectVisible);
        QVERIFY(w.startButton()->isEnabled());
        QVERIFY(!w.saveButton()->isEnabled());
        // The live attitude reaches the display (polled "read all").
        QTRY_VERIFY_WITH_TIMEOUT(w.poseView()->pose().has_value(), 3000);
        QVERIFY(std::abs(w.poseView()->pose()->pitch - MotionModel::kStaticPitchDeg) < 0.5);
        // Grab exercises the painter on every method's display.
        QVERIFY(!w.poseView()->grab().isNull());
    }

    void planarRun()
    {
        serve(Motion::Spin);
        QTemporaryDir history;
        Hec495CalibrationWizard w(*m_session);
        w.runSaver().setRoot(history.path());
        model::DeviceIdentity id;
        id.productName = "HEC495";
        id.busAddress = 80;
        w.runSaver().setIdentity(id);
        toRunPage(w, CompassCalMethod::Planar);
        QVERIFY(click(w, w.startButton()).ok());
        QVERIFY(w.running());
        QVERIFY(w.stopButton()->isEnabled());
        QVERIFY(w.saveButton()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(w.tracker().validPoints() >= 6 && w.tracker().collectedCount() >= 3, 12000);
        QVERIFY(!w.poseView()->grab().isNull());
        // An automatic method asks first: "Not yet" sends nothing and the run goes on.
        QVERIFY(w.saveConfirmation()->isHidden());
        QSignalSpy sent(&w, &Hec495CalibrationWizard::requestFinished);
        w.saveButton()->click();
        QVERIFY(w.saveConfirmation()->isVisibleTo(&w));
        QVERIFY(!w.saveButton()->isEnabled());
        w.cancelSaveButton()->click();
        QVERIFY(w.saveConfirmation()->isHidden());
        QTest::qWait(300); // duration under test: "Not yet" sends no save request within 300 ms
        QCOMPARE(sent.size(), 0);
        QVERIFY(w.running() && !w.saved());
        bool active = false;
        withSim(*m_pty, [&](Hec495Simulator &d) { active = d.calibration().active(); });
        QVERIFY(active); // the module still collects: nothing was saved
        QVERIFY(w.statusText().contains(QStringLiteral("Not saved yet")));
        w.saveButton()->click();
        QVERIFY(w.saveConfirmation()->isVisibleTo(&w));
        const auto r = click(w, w.confirmSaveButton());
        QVERIFY2(r.ok(), qPrintable(w.errorText()));
        QTRY_COMPARE(w.currentId(), int(Hec495CalibrationWizard::ResultPage));
        QVERIFY(w.saved());
        float fit = -1;
        withSim(*m_pty, [&](Hec495Simulator &d) { fit = d.lastFitError(); });
        QCOMPARE(*w.fitError(), fit);
        QVERIFY(w.savedPoints() >= 6);
        QCOMPARE(w.savedPoints(), r.reply.points);
        // Targets were lit as the compass turned (each point at most one target).
        QVERIFY(w.tracker().collectedCount() >= 3);
        QVERIFY(w.tracker().collectedCount() <= w.savedPoints());
        QVERIFY(w.resultText().contains(QString::number(double(fit), 'f', 2)));
        QVERIFY(w.resultText().contains(QStringLiteral("Points used: %1").arg(w.savedPoints())));
        const calib::CalibrationHistory h(history.path());
        const auto runs = h.list(QStringLiteral("HEC495-addr80"));
        QCOMPARE(runs.size(), 1);
        QCOMPARE(runs[0].kind, QStringLiteral("compass"));
        QCOMPARE(runs[0].result.value(QStringLiteral("fit_err")).toDouble(), double(fit));
        QCOMPARE(runs[0].result.value(QStringLiteral("points")).toInt(), w.savedPoints());
        QCOMPARE(runs[0].verdict(), QLatin1String(fit > 10.0f ? "fail" : "pass"));
        calib::SampleTable samples;
        QVERIFY(h.loadSamples(runs[0], samples));
        QVERIFY(samples.rows.size() > 5);
        QVERIFY(w.resultText().contains(QDir::toNativeSeparators(runs[0].folder)));
        QCOMPARE(w.redoRecommended(), fit > 10.0f);
        QVERIFY(w.resultText().contains(w.redoRecommended() ? QStringLiteral("calibrate again")
                                                            : QStringLiteral("Good")));
        // "Calibrate again" goes back to the run page with a fresh run.
        w.againButton()->click();
        QCOMPARE(w.currentId(), int(Hec495CalibrationWizard::RunPage));
        QVERIFY(!w.saved());
        QCOMPARE(w.tracker().collectedCount(), 0);
        QVERIFY(w.startButton()->isEnabled());
    }

    void manualCollectStopClear()
    {
        // Manual method (0x65): each "Collect point" (0x67) is answered by 0x66 with the count.
        serve(Motion::Static);
        Hec495CalibrationWizard w(*m_session);
        toRunPage(w, CompassCalMethod::Manual);
        QVERIFY(!w.collectButton()->isEnabled());
        QVERIFY(click(w, w.startButton()).ok());
        QVERIFY(w.collectButton()->isEnabled());
        for (int i = 1; i <= 3; ++i) {
            const auto r = click(w, w.collectButton());
            QVERIFY(r.ok());
            QCOMPARE(r.reply.points, i);
            QTRY_COMPARE(w.tracker().validPoints(), i);
        }
        int simPoints = 0;
        withSim(*m_pty, [&](Hec495Simulator &d) { simPoints = d.calibration().points(); });
        QCOMPARE(simPoints, 3);
        // Stop (0x12) abandons the run: nothing saved, the count starts over.
        QVERIFY(click(w, w.stopButton()).ok());
        QVERIFY(!w.running());
        QCOMPARE(w.tracker().validPoints(), 0);
        QVERIFY(w.statusText().contains(QStringLiteral("nothing was saved")));
        bool active = true;
        withSim(*m_pty, [&](Hec495Simulator &d) { active = d.calibration().active(); });
        QVERIFY(!active);
        // Clear (0x10) is accepted outside a run.
        QVERIFY(w.clearButton()->isEnabled());
        QVERIFY(click(w, w.clearButton()).ok());
        QVERIFY(w.statusText().contains(QStringLiteral("cleared")));
        QVERIFY(w.startButton()->isEnabled());
    }

    void saveFailsThenClosed()
    {
        // Static pose pitched 2.5 deg: outside the planar method's 2 deg, so no point.
        serve(Motion::Static);
        Hec495CalibrationWizard w(*m_session);
        toRunPage(w, CompassCalMethod::Planar);
        QVERIFY(click(w, w.startButton()).ok());
        w.saveButton()->click();
        const auto r = click(w, w.confirmSaveButton());
        QCOMPARE(r.status, Hec495Result::Status::Refused);
        QCOMPARE(w.currentId(), int(Hec495CalibrationWizard::RunPage));
        QVERIFY(!w.saved());
        QVERIFY(w.errorText().startsWith(QStringLiteral("Failed")));
        QVERIFY(w.errorText().contains(QStringLiteral("too few points")));
        QVERIFY(w.startButton()->isEnabled());
        QVERIFY(!w.validateCurrentPage());
        // The connection goes away: starting says so and what to do.
        m_session->close();
        QTRY_COMPARE(m_session->state(), device::SessionState::Closed);
        const auto closed = click(w, w.startButton());
        QVERIFY(!closed.ok());
        QVERIFY(w.errorText().contains(QStringLiteral("connect to the compass again")));
        QVERIFY(!w.running());
    }
};

IMUDESK_TEST_MAIN(TstHec495CalibrationWizard)
#include "tst_hec495_calibration_wizard.moc"
