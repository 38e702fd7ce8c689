// Configuration panel and mounting picker, offscreen, against the simulator on a
// pseudo-terminal: read all, greyed-out rows, pending commands and the CLI line, apply
// with replies shown, the factory-reset confirmation, the link-load warning, actions per
// firmware, and the picker by picture, code and directions (left-handed refused).
#include "configuration/config_panel.h"
#include "models/settings_table_model.h"
#include "configuration/mounting_picker.h"
#include "configuration/mounting_tile.h"
#include "sim/pty_simulator.h"

#include <QApplication>
#include <QClipboard>
#include <QComboBox>
#include <QPushButton>
#include <QSignalSpy>
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
    explicit Bench(const char *firmware = "1.7.1", const char *model = "HI14") : simulator(opts(firmware, model)) {}
    static sim::SimOptions opts(const char *firmware, const char *model)
    {
        sim::SimOptions o;
        o.firmware = firmware;
        o.model = model;
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

QTEST_MAIN(TstConfigPanel)
#include "tst_config_panel.moc"
