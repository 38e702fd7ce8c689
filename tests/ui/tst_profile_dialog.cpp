// Profile dialog and bandwidth calculator, offscreen, against simulators on
// pseudo-terminals: save a device's profile, load it on another (table of differences),
// apply with read-back, apply to further ports with a report per device; the calculator
// against the manuals' table of maximum rates.
#include "charts/bandwidth_calculator.h"
#include "configuration/profile_dialog.h"
#include "sim/pty_simulator.h"
#include "../common/test_main.h"

#include <QFile>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace imudesk;
using settings::ConfigurationController;
using Msg = protocol::hipnuc::Message;

namespace {

struct Device {
    std::unique_ptr<sim::PtySimulator> simulator;
    device::DeviceSession session;
    explicit Device(uint64_t seed)
    {
        sim::SimOptions o;
        o.seed = seed;
        simulator = std::make_unique<sim::PtySimulator>(o);
    }
    bool start()
    {
        if (!simulator->start())
            return false;
        session.setAutoReconnect(false);
        QSignalSpy identified(&session, &device::DeviceSession::identityQueryFinished);
        session.open(simulator->devicePath(), 115200);
        return identified.wait(5000);
    }
};

bool read(ui::ProfileDialog &d)
{
    QSignalSpy done(&d.controller(), &ConfigurationController::readFinished);
    d.readDevice();
    return done.wait(10000) && done.first().at(0).toBool();
}

} // namespace

class TstProfileDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void saveLoadDiffApplyBatch()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("p.json"));
        Device a(11), b(12);
        QVERIFY(a.start());
        QVERIFY(b.start());
        {
            ui::ProfileDialog da(a.session);
            QVERIFY(read(da));
            QSignalSpy applied(&da.controller(), &ConfigurationController::applyFinished);
            da.controller().apply({{QStringLiteral("IMU.URFR"), QStringLiteral("304")},
                                   {QStringLiteral("ATT.MODE"), QStringLiteral("0")}});
            QVERIFY(applied.wait(15000));
            QString error;
            QVERIFY2(da.saveProfile(path, &error), qPrintable(error));
        }
        ui::ProfileDialog db(b.session);
        QVERIFY(read(db));
        QString error;
        QVERIFY2(db.loadProfile(path, &error), qPrintable(error));
        QCOMPARE(db.diffTable()->rowCount(), 2);
        QCOMPARE(db.diffTable()->item(0, 0)->text(), QStringLiteral("ATT.MODE"));
        QCOMPARE(db.diffTable()->item(1, 1)->text(), QStringLiteral("304"));
        QCOMPARE(db.diffTable()->item(1, 2)->text(), QStringLiteral("24"));
        QSignalSpy applied(&db.controller(), &ConfigurationController::applyFinished);
        db.applyToDevice();
        QVERIFY(applied.wait(15000));
        QVERIFY(applied.first().at(0).value<ConfigurationController::ApplyReport>().ok);
        QCOMPARE(db.diffTable()->rowCount(), 0);
        QVERIFY(db.statusText().contains(QLatin1String("verified")));

        // Another port, not connected: the batch connects, applies, saves and reports.
        sim::SimOptions o;
        o.seed = 13;
        sim::PtySimulator c(o);
        QVERIFY(c.start());
        QSignalSpy finished(&db, &ui::ProfileDialog::batchFinished);
        db.applyToPorts({c.devicePath()});
        QVERIFY(finished.wait(30000));
        QCOMPARE(db.batchTable()->rowCount(), 1);
        std::string uuid;
        int saved = 0;
        c.withDevice([&](sim::HipnucSimulator &d) {
            uuid = d.uuid();
            saved = d.savedConfig().urfrCode;
        });
        QCOMPARE(db.batchTable()->item(0, 1)->text(), QString::fromStdString(uuid));
        QVERIFY(db.batchTable()->item(0, 3)->text().startsWith(QLatin1String("OK")));
        QCOMPARE(saved, 304);
    }

    void loadRefusesBadFiles()
    {
        Device a(14);
        QVERIFY(a.start());
        ui::ProfileDialog d(a.session);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format":"imudesk-profile","version":1,"settings":{"PMUX2.DIV":"0"}})");
        f.close();
        QString error;
        QVERIFY(!d.loadProfile(path, &error));
        QVERIFY(d.statusText().contains(QLatin1String("PMUX2.DIV")));
    }

    void calculatorMatchesTheManual_data()
    {
        QTest::addColumn<int>("baud");
        QTest::addColumn<QString>("hi91");
        QTest::newRow("9600") << 9600 << "10 Hz";
        QTest::newRow("115200") << 115200 << "100 Hz";
        QTest::newRow("230400") << 230400 << "250 Hz";
        QTest::newRow("460800") << 460800 << "500 Hz";
        QTest::newRow("921600") << 921600 << "1000 Hz";
    }
    void calculatorMatchesTheManual()
    {
        QFETCH(int, baud);
        QFETCH(QString, hi91);
        ui::BandwidthCalculator w;
        w.setBaud(baud);
        QCOMPARE(w.maxRateText(Msg::HI91), hi91);
    }

    void calculatorWarns()
    {
        ui::BandwidthCalculator w;
        QSignalSpy changed(&w, &ui::BandwidthCalculator::resultChanged);
        w.setBaud(115200);
        w.setRate(Msg::HI91, 100);
        QVERIFY(w.result().fits);
        QVERIFY(w.warningText().isEmpty());
        w.setRate(Msg::HI91, 500);
        QVERIFY(!w.result().fits);
        QVERIFY(w.warningText().contains(QLatin1String("460800")));
        QVERIFY(!changed.last().at(0).toBool());
        w.setBaud(921600);
        QVERIFY(w.result().fits);
        settings::DeviceConfiguration cfg;
        cfg.values = {{QStringLiteral("SERIAL.BAUD"), QStringLiteral("115200")},
                      {QStringLiteral("LOG.HI91"), QStringLiteral("0.005")}};
        w.setConfiguration(cfg);
        QCOMPARE(w.result().baud, 115200);
        QCOMPARE(w.result().bytesPerSecond, 82.0 * 200);
    }
};

IMUDESK_TEST_MAIN(TstProfileDialog)
#include "tst_profile_dialog.moc"
