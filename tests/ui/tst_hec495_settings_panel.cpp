// Hec495SettingsPanel offscreen, bound to a Hec495Session on the simulated HEC495 over a
// pseudo-terminal: each control sends its command, the result shows, the module changes.
#include "device/hec495_session.h"
#include "configuration/hec495_settings_panel.h"
#include "protocol/witlink/commands.h"
#include "sim/hec495_simulator.h"
#include "sim/pty_simulator.h"
#include "../common/test_main.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include <cmath>
#include <functional>
#include <memory>

using namespace imudesk;
using namespace imudesk::sim;
using imudesk::device::Hec495Result;
using imudesk::device::Hec495Session;
using imudesk::ui::Hec495SettingsPanel;

namespace {

void withSim(PtySimulator &pty, const std::function<void(Hec495Simulator &)> &fn)
{
    pty.withSerialDevice([&fn](SimulatedSerialDevice &d) { fn(dynamic_cast<Hec495Simulator &>(d)); });
}

} // namespace

class TstHec495SettingsPanel : public QObject {
    Q_OBJECT
    std::unique_ptr<PtySimulator> m_pty;
    std::unique_ptr<Hec495Session> m_session;

    // Clicks a button and waits for the panel's result.
    Hec495Result click(Hec495SettingsPanel &panel, QPushButton *button)
    {
        QSignalSpy done(&panel, &Hec495SettingsPanel::requestFinished);
        button->click();
        if (!panel.busy() && done.isEmpty())
            qFatal("the click sent nothing");
        if (!done.wait(5000))
            qFatal("no result");
        return done.at(0).at(0).value<Hec495Result>();
    }

private Q_SLOTS:
    void init()
    {
        Hec495Options o;
        o.baud = 115200;
        m_pty = std::make_unique<PtySimulator>(std::make_unique<Hec495Simulator>(o));
        QVERIFY(m_pty->start());
        m_session = std::make_unique<Hec495Session>();
        m_session->setPollingRate(0);
        m_session->open(m_pty->devicePath(), 115200);
        QTRY_COMPARE_WITH_TIMEOUT(m_session->state(), device::SessionState::Connected, 5000);
    }
    void cleanup()
    {
        m_session.reset();
        m_pty.reset();
    }

    void declination()
    {
        Hec495SettingsPanel panel(m_session.get());
        panel.declinationBox()->setValue(-3.2);
        QVERIFY(click(panel, panel.setDeclinationButton()).ok());
        QVERIFY(panel.statusText().contains(QLatin1String("success")));
        double running = 0;
        withSim(*m_pty, [&](Hec495Simulator &d) { running = d.runningSettings().declination; });
        QCOMPARE(running, -3.2);
        panel.declinationBox()->setValue(0);
        QVERIFY(click(panel, panel.readDeclinationButton()).ok());
        QCOMPARE(panel.declinationBox()->value(), -3.2);
    }

    void rateContentAddressSaveReset()
    {
        Hec495SettingsPanel panel(m_session.get());
        panel.setConfirmReset(false);
        panel.rateBox()->setCurrentIndex(panel.rateBox()->findData(50));
        QVERIFY(click(panel, panel.setRateButton()).ok());
        QTRY_VERIFY(m_session->streaming());
        panel.contentBox()->setCurrentIndex(2);
        QVERIFY(click(panel, panel.setContentButton()).ok());
        panel.addressBox()->setValue(9);
        QVERIFY(click(panel, panel.setAddressButton()).ok());
        QTRY_COMPARE(m_session->address(), 9);
        QVERIFY(click(panel, panel.saveButton()).ok());
        Hec495Simulator::Settings saved;
        withSim(*m_pty, [&](Hec495Simulator &d) { saved = d.savedSettings(); });
        QCOMPARE(saved.rateHz, 50);
        QCOMPARE(int(saved.content), 2);
        QCOMPARE(int(saved.address), 9);
        QVERIFY(click(panel, panel.resetButton()).ok());
        QTRY_COMPARE(m_session->baud(), 9600);
        QCOMPARE(panel.baudBox()->currentData().toInt(), 9600);
        QCOMPARE(panel.addressBox()->value(), 0);
    }

    // 2.1-2.4: each single reading is sent and answered; the answer shows in the status line.
    // 2.17: the address query puts the module's address in the box.
    void singleReadingsAndAddressQuery()
    {
        Hec495SettingsPanel panel(m_session.get());
        panel.angleBox()->setCurrentIndex(3); // pitch, roll and heading (2.4)
        auto r = click(panel, panel.readAngleButton());
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(r.reply.kind, protocol::witlink::Reply::Kind::Angles);
        QVERIFY2(panel.statusText().contains(QLatin1String("heading")), qPrintable(panel.statusText()));
        const double pitch = r.reply.pitch, heading = r.reply.heading;
        const protocol::witlink::Command singles[] = {protocol::witlink::Command::ReadPitch,
                                                      protocol::witlink::Command::ReadRoll,
                                                      protocol::witlink::Command::ReadHeading};
        for (int i = 0; i < 3; ++i) {
            panel.angleBox()->setCurrentIndex(i);
            r = click(panel, panel.readAngleButton());
            QVERIFY2(r.ok(), qPrintable(r.message));
            QCOMPARE(r.reply.kind, protocol::witlink::Reply::Kind::Angle);
            QCOMPARE(r.reply.request, uint8_t(singles[i]));
            QVERIFY2(panel.statusText().contains(QLatin1String(" deg")), qPrintable(panel.statusText()));
        }
        // The still module's heading (2.3) and pitch (2.1) agree with the three-angle reading.
        QVERIFY2(std::abs(r.reply.angle - heading) < 2.0, qPrintable(QStringLiteral("%1 %2").arg(r.reply.angle).arg(heading)));
        panel.angleBox()->setCurrentIndex(0);
        r = click(panel, panel.readAngleButton());
        QVERIFY(std::abs(r.reply.angle - pitch) < 1.0);
        panel.addressBox()->setValue(42);
        r = click(panel, panel.readAddressButton());
        QVERIFY2(r.ok(), qPrintable(r.message));
        QCOMPARE(panel.addressBox()->value(), 0);
    }

    void baudAndFailure()
    {
        Hec495SettingsPanel panel(m_session.get());
        panel.baudBox()->setCurrentIndex(panel.baudBox()->findData(19200));
        QVERIFY(click(panel, panel.setBaudButton()).ok());
        QTRY_COMPARE(m_session->baud(), 19200);
        // Closed port: the request fails and says so; the controls come back.
        m_session->close();
        QTRY_COMPARE(m_session->state(), device::SessionState::Closed);
        const auto r = click(panel, panel.saveButton());
        QVERIFY(!r.ok());
        QVERIFY(panel.statusText().startsWith(QLatin1String("Failed")));
        QVERIFY(panel.saveButton()->isEnabled());
    }
};

IMUDESK_TEST_MAIN(TstHec495SettingsPanel)
#include "tst_hec495_settings_panel.moc"
