// Configuration panel and mounting picker, offscreen, against the simulator on a
// pseudo-terminal: read all, greyed-out rows, pending commands and the CLI line, apply
// with replies shown, the factory-reset confirmation, the link-load warning, actions per
// firmware, and the picker by picture, code and directions (left-handed refused).
#include "configuration/config_panel.h"
#include "itemmodels/settings_table_model.h"
#include "configuration/mounting_picker.h"
#include "configuration/mounting_tile.h"
#include "sim/pty_simulator.h"
#include "../common/test_main.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QPushButton>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QTextDocument>
#include <QTableView>
#include <QTest>

using namespace imudesk;
using models::SettingsTableModel;
using settings::ConfigurationController;
using ui::ConfigPanel;
using ui::MountingPicker;
using Dir = settings::MountingChoice::Direction;

namespace {

struct Bench {
    sim::PtySimulator simulator;
    device::DeviceSession session;
    ConfigPanel panel{session};
    explicit Bench(const char *firmware = "1.7.1", const char *model = "HI14",
                   sim::SimFaults::ComConfigStyle comConfig = sim::SimFaults::ComConfigStyle::KeyValue)
        : simulator(opts(firmware, model, comConfig))
    {
    }
    static sim::SimOptions opts(const char *firmware, const char *model, sim::SimFaults::ComConfigStyle comConfig)
    {
        sim::SimOptions o;
        o.firmware = firmware;
        o.model = model;
        o.faults.comConfigStyle = comConfig;
        return o;
    }
    bool start()
    {
        if (!simulator.start())
            return false;
        session.setAutoReconnect(false);
        QSignalSpy identified(&session, &device::DeviceSession::identityQueryFinished);
        session.open(simulator.devicePath(), 115200);
        if (!identified.wait(5000))
            return false;
        panel.setPortName(simulator.devicePath());
        QSignalSpy read(&panel.controller(), &ConfigurationController::readFinished);
        panel.button(QStringLiteral("read"))->click();
        return read.wait(10000) && read.first().at(0).toBool();
    }
    QModelIndex cell(const char *key, int column)
    {
        return panel.model().index(panel.model().rowOfKey(QLatin1String(key)), column);
    }
};

} // namespace

class TstConfigPanel : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // Device > Configuration on a connected module: the panel reads every setting as it opens
    // (before, the table stayed empty until Read all); shown again later, it reads no more.
    void readsTheDeviceWhenItOpens()
    {
        Bench b;
        QVERIFY(b.simulator.start());
        b.session.setAutoReconnect(false);
        QSignalSpy identified(&b.session, &device::DeviceSession::identityQueryFinished);
        b.session.open(b.simulator.devicePath(), 115200);
        QVERIFY(identified.wait(5000));
        QVERIFY(!b.panel.controller().identity().usable());
        QSignalSpy read(&b.panel.controller(), &ConfigurationController::readFinished);
        b.panel.show();
        QVERIFY(read.wait(10000));
        QVERIFY(read.first().at(0).toBool());
        QVERIFY(b.panel.controller().identity().usable());
        QVERIFY(b.cell("ATT.MODE", SettingsTableModel::DeviceColumn).data().toString().startsWith(QLatin1String("1")));
        b.panel.hide();
        b.panel.show();
        QCoreApplication::processEvents();
        QVERIFY(!b.panel.controller().busy());
        QCOMPARE(read.count(), 1);
    }

    // The output-rate editor: every choice in full ("200 Hz (0.005 s)", not "200… s)"), the
    // editor as wide as its text, and a choice from the list counts at once (before, only
    // after Enter).
    void outputRateEditorReadableAndImmediate()
    {
        Bench b;
        QVERIFY(b.start());
        b.panel.resize(420, 600); // a narrow right column
        b.panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&b.panel));
        const QModelIndex cell = b.cell("LOG.HI91", SettingsTableModel::NewColumn);
        QVERIFY(cell.isValid());
        b.panel.table()->scrollTo(cell);
        b.panel.table()->edit(cell);
        QComboBox *box = nullptr;
        QTRY_VERIFY((box = b.panel.table()->viewport()->findChild<QComboBox *>()) != nullptr);
        const int at = box->findData(QStringLiteral("0.005"));
        QVERIFY(at >= 0);
        QCOMPARE(box->itemText(at), QStringLiteral("200 Hz (0.005 s)"));
        QCOMPARE(box->itemText(box->findData(QStringLiteral("1"))), QStringLiteral("1 Hz (1 s)"));
        const QFontMetrics fm = box->view()->fontMetrics();
        for (int i = 0; i < box->count(); ++i)
            QVERIFY2(box->view()->minimumWidth() >= fm.horizontalAdvance(box->itemText(i)),
                     qPrintable(box->itemText(i)));
        QVERIFY2(box->width() >= box->sizeHint().width() || box->width() == b.panel.table()->viewport()->width(),
                 qPrintable(QStringLiteral("%1 < %2").arg(box->width()).arg(box->sizeHint().width())));
        QVERIFY(box->geometry().right() < b.panel.table()->viewport()->width());
        // A click on an item in the list: the pending change is there without Enter.
        box->setCurrentIndex(at);
        Q_EMIT box->activated(at);
        QTRY_VERIFY(b.panel.pendingText().contains(QLatin1String("> LOG HI91 ONTIME 0.005")));
        QTRY_VERIFY(!b.panel.table()->viewport()->findChild<QComboBox *>()
                    || !b.panel.table()->viewport()->findChild<QComboBox *>()->isVisible());
    }

    void readEditApply()
    {
        Bench b;
        QVERIFY(b.start());
        QVERIFY(b.cell("ATT.MODE", SettingsTableModel::DeviceColumn).data().toString().startsWith(QLatin1String("1")));
        QVERIFY(!(b.panel.model().flags(b.cell("IMU_EN_MCAL", SettingsTableModel::NewColumn)) & Qt::ItemIsEnabled));
        QVERIFY(!b.panel.button(QStringLiteral("apply"))->isEnabled());
        QVERIFY(b.panel.model().setPending(QStringLiteral("IMU.URFR"), QStringLiteral("205")));
        QVERIFY(b.panel.model().setPending(QStringLiteral("LOG.HI91"), QStringLiteral("0.02")));
        QVERIFY(b.panel.pendingText().contains(QLatin1String("> CONFIG IMU URFR 205")));
        QVERIFY(b.panel.pendingText().contains(QLatin1String("> LOG HI91 ONTIME 0.02")));
        const QString line = QStringLiteral("imudesk-cli config %1 set LOG.HI91=0.02 IMU.URFR=205")
                                 .arg(b.simulator.devicePath());
        QCOMPARE(b.panel.cliLine(), line);
        b.panel.button(QStringLiteral("copy"))->click();
        QCOMPARE(QApplication::clipboard()->text(), line);
        QVERIFY(b.panel.button(QStringLiteral("apply"))->isEnabled());
        QSignalSpy applied(&b.panel.controller(), &ConfigurationController::applyFinished);
        b.panel.button(QStringLiteral("apply"))->click();
        QVERIFY(applied.wait(15000));
        QVERIFY(applied.first().at(0).value<ConfigurationController::ApplyReport>().ok);
        QCOMPARE(b.cell("IMU.URFR", SettingsTableModel::DeviceColumn).data().toString(), QStringLiteral("205"));
        QVERIFY(b.panel.model().pendingChanges().empty());
        QVERIFY(b.panel.replyLog().contains(QLatin1String("> CONFIG IMU URFR 205")));
        QVERIFY(b.panel.replyLog().contains(QLatin1String("IMU.URFR=205: verified")));
    }

    // A module whose LOG COMCONFIG reply ImuDesk cannot read: the write is "could not be read
    // back", in amber, with the reply; never "not taken" (issue 35).
    void unreadableReadBackIsNotNotTaken()
    {
        Bench b("1.7.1", "HI14", sim::SimFaults::ComConfigStyle::Unlabelled);
        QVERIFY(b.start());
        QVERIFY(b.panel.model().setPending(QStringLiteral("IMU.URFR"), QStringLiteral("205")));
        QSignalSpy applied(&b.panel.controller(), &ConfigurationController::applyFinished);
        b.panel.applyPending();
        QVERIFY(applied.wait(15000));
        const auto report = applied.first().at(0).value<ConfigurationController::ApplyReport>();
        QVERIFY(!report.ok);
        QCOMPARE(int(report.results.size()), 1);
        QCOMPARE(report.results.front().outcome, ConfigurationController::Outcome::Unconfirmed);
        QVERIFY2(b.panel.replyLog().contains(QLatin1String("IMU.URFR=205: could not be read back")), qPrintable(b.panel.replyLog()));
        QVERIFY(!b.panel.replyLog().contains(QLatin1String("not taken")));
        QVERIFY(b.panel.replyLog().contains(QLatin1String("the reply was: 115200")));
        QPlainTextEdit *log = nullptr;
        for (auto *e : b.panel.findChildren<QPlainTextEdit *>())
            if (e->toPlainText().contains(QLatin1String("could not be read back")))
                log = e;
        QVERIFY(log);
        QVERIFY2(log->document()->toHtml().contains(QLatin1String("#b26a00")), "the line is amber");
        // The module took it all the same.
        sim::HipnucSimulator::Config running;
        b.simulator.withDevice([&running](sim::HipnucSimulator &d) { running = d.runningConfig(); });
        QCOMPARE(running.urfrCode, 205);
    }

    void refusedReplyShown()
    {
        Bench b;
        QVERIFY(b.start());
        b.simulator.withDevice([](sim::HipnucSimulator &d) { d.setRefusedCommand("CONFIG ATT MODE"); });
        QVERIFY(b.panel.model().setPending(QStringLiteral("ATT.MODE"), QStringLiteral("0")));
        QSignalSpy applied(&b.panel.controller(), &ConfigurationController::applyFinished);
        b.panel.applyPending();
        QVERIFY(applied.wait(15000));
        QVERIFY(b.panel.replyLog().contains(QLatin1String("refused (ERR)")));
        // The table shows what the device holds, and the wish stays pending.
        QVERIFY(b.cell("ATT.MODE", SettingsTableModel::DeviceColumn).data().toString().startsWith(QLatin1String("1")));
        QCOMPARE(int(b.panel.model().pendingChanges().size()), 1);
    }

    void factoryResetAsksFirst()
    {
        Bench b;
        QVERIFY(b.start());
        QString asked;
        bool answer = false;
        b.panel.setConfirm([&](const QString &, const QString &text) {
            asked = text;
            return answer;
        });
        QSignalSpy sent(&b.panel.controller(), &ConfigurationController::commandSent);
        b.panel.button(QStringLiteral("freset"))->click();
        QVERIFY(asked.contains(QLatin1String("lost")));
        QCOMPARE(sent.count(), 0);
        answer = true;
        QSignalSpy done(&b.panel.controller(), &ConfigurationController::actionFinished);
        b.panel.button(QStringLiteral("freset"))->click();
        QVERIFY(done.wait(15000));
        QVERIFY(done.first().at(1).toBool());
        QCOMPARE(sent.first().at(0).toString(), QStringLiteral("FRESET"));
    }

    void linkWarning()
    {
        Bench b;
        QVERIFY(b.start());
        QVERIFY(!b.panel.linkText().contains(QLatin1String("lost")));
        QVERIFY(b.panel.model().setPending(QStringLiteral("LOG.HI91"), QStringLiteral("0.002")));
        QVERIFY(b.panel.linkText().contains(QLatin1String("frames will be lost")));
        bool asked = false;
        b.panel.setConfirm([&](const QString &, const QString &) {
            asked = true;
            return false;
        });
        QSignalSpy sent(&b.panel.controller(), &ConfigurationController::commandSent);
        b.panel.applyPending();
        QVERIFY(asked);
        QCOMPARE(sent.count(), 0);
    }

    void actionsPerFirmware()
    {
        Bench b("1.6.6");
        QVERIFY(b.start());
        QVERIFY(!b.panel.button(QStringLiteral("ATT.RST.1"))->isEnabled());
        QVERIFY(b.panel.button(QStringLiteral("ATT.RST.3"))->isEnabled());
        QVERIFY(b.panel.button(QStringLiteral("ATT.RST.3"))->toolTip().contains(QLatin1String("5 deg")));
        QVERIFY(b.panel.button(QStringLiteral("YAW"))->isEnabled());
        QVERIFY(!(b.panel.model().flags(b.cell("IMU.COORD", SettingsTableModel::NewColumn)) & Qt::ItemIsEnabled));
        QSignalSpy done(&b.panel.controller(), &ConfigurationController::actionFinished);
        b.panel.button(QStringLiteral("YAW"))->click();
        QVERIFY(done.wait(5000));
        QVERIFY(done.first().at(1).toBool());
        QVERIFY(b.panel.replyLog().contains(QLatin1String("> CONFIG YAW 1 0")));
    }

    void pickerByPictureCodeAndDirections()
    {
        MountingPicker p(24, false);
        QCOMPARE(p.code(), 24);
        QVERIFY(p.tile(24)->isChecked());
        QSignalSpy changed(&p, &MountingPicker::codeChanged);
        QTest::mouseClick(p.tile(205), Qt::LeftButton);
        QCOMPARE(p.code(), 205);
        QVERIFY(p.tile(205)->isChecked());
        QVERIFY(!p.tile(24)->isChecked());
        QCOMPARE(p.commandText(), QStringLiteral("CONFIG IMU URFR 205"));
        p.codeBox()->setCurrentIndex(p.codeBox()->findData(531));
        QCOMPARE(p.code(), 531);
        QVERIFY(p.setDirections(Dir::Right, Dir::Down));
        QCOMPARE(p.code(), 43); // the manual: IMU X right, IMU Y down, IMU Z forward
        QVERIFY(!p.setDirections(Dir::Up, Dir::Down));
        QVERIFY(!p.errorText().isEmpty());
        QCOMPARE(p.code(), 43); // unchanged
        QCOMPARE(changed.count(), 3);
        MountingPicker legacy(43, true); // v1.6.6: the manual's "Y down" matrix
        QCOMPARE(legacy.commandText(), QStringLiteral("CONFIG IMU URFR 1,0,0,0,0,1,0,-1,0"));
        p.resize(900, 700);
        QVERIFY(!p.tile(43)->grab().isNull());
    }
};

IMUDESK_TEST_MAIN(TstConfigPanel)
#include "tst_config_panel.moc"
