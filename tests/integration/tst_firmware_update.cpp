// imudesk-cli update end to end over a pseudo-terminal: the simulated module (in this
// process, PtySimulator, or as `imudesk-cli simulate --flash-dump`) is updated by the CLI
// process. Happy path, each injected fault followed by a successful second attempt, files
// refused before any byte is sent, cancel (SIGINT) mid-write and resume.
#include "../common/cli_run.h"
#include "../common/firmware_files.h"
#include "../common/test_main.h"
#include "core/firmware/serial_byte_link.h"
#include "protocol/ihex/firmware_image.h"
#include "protocol/ihex/intel_hex_writer.h"
#include "sim/kboot_bootloader.h"
#include "sim/pty_simulator.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <unistd.h>

using namespace imudesk;
using protocol::ihex::FirmwareImage;
using protocol::ihex::IntelHexWriter;
using sim::HipnucSimulator;
using sim::KbootBootloader;

namespace {

constexpr int kBaud = 921600;

using Run = imudesk::test::CliResult;

Run cli(const QStringList &args, int timeoutMs = 60000)
{
    return imudesk::test::runCli(args, timeoutMs);
}

using imudesk::test::resultLine;
using imudesk::test::writeFile;

FirmwareImage image(const std::string &version, size_t size, uint64_t seed = 11)
{
    return imudesk::test::appImage(version, size, seed);
}

bool flashHolds(sim::PtySimulator &s, const FirmwareImage &img, std::string *version = nullptr)
{
    bool same = false;
    s.withDevice([&](HipnucSimulator &d) {
        const auto &f = d.bootloader().flash();
        same = std::equal(img.data.begin(), img.data.end(), f.begin() + img.startAddress);
        if (version)
            *version = d.state() == HipnucSimulator::State::App ? d.firmware().toString() : std::string("bootloader");
    });
    return same;
}

sim::SimOptions fastModule()
{
    sim::SimOptions o;
    o.baud = kBaud;
    return o;
}

} // namespace

class TstFirmwareUpdate : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private Q_SLOTS:
    void happyPathFlashDump()
    {
        const QString dump = m_dir.filePath(QStringLiteral("flash.bin"));
        QProcess simulator;
        simulator.start(QString::fromUtf8(IMUDESK_CLI_PATH),
                        {"simulate", "--pty", "--baud", QString::number(kBaud), "--flash-dump", dump});
        QVERIFY(simulator.waitForStarted());
        QTRY_VERIFY_WITH_TIMEOUT(simulator.canReadLine(), 10000);
        const QString pty = QString::fromUtf8(simulator.readLine()).trimmed().mid(5);
        const auto img = image("1.7.2", 40 * 1024 + 1);
        const QString hex = writeFile(m_dir, QStringLiteral("fw172.hex"), IntelHexWriter::write(img));
        const auto r = cli({"update", pty, hex, "--baud", QString::number(kBaud), "--json"});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        const auto res = resultLine(r.out);
        QCOMPARE(res.value("ok").toBool(), true);
        QCOMPARE(res.value("verified").toString(), QStringLiteral("read-back"));
        QCOMPARE(res.value("firmware_before").toString(), QStringLiteral("1.7.1"));
        QCOMPARE(res.value("firmware_after").toString(), QStringLiteral("1.7.2"));
        QVERIFY(r.out.contains(QStringLiteral("\"event\":\"progress\"")));
        ::kill(pid_t(simulator.processId()), SIGTERM);
        QVERIFY(simulator.waitForFinished(5000));
        QCOMPARE(simulator.exitCode(), 0);
        QFile f(dump);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray flash = f.readAll();
        QCOMPARE(flash.size(), 512 * 1024 - 0x8000);
        QCOMPARE(QByteArray(flash.constData(), int(img.data.size())),
                 QByteArray(reinterpret_cast<const char *>(img.data.data()), int(img.data.size())));
        // the word padding and the rest of the erased sectors stay 0xFF
        QCOMPARE(uint8_t(flash.at(int(img.data.size()))), uint8_t(0xFF));
        QCOMPARE(uint8_t(flash.at(44 * 1024 - 1)), uint8_t(0xFF));
    }

    void faultThenSecondAttempt_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("needle");
        QTest::newRow("silence") << 1 << QStringLiteral("did not answer");
        QTest::newRow("corrupted reply") << 2 << QStringLiteral("damaged bytes");
        QTest::newRow("power loss mid-write") << 3 << QStringLiteral("did not answer");
    }
    void faultThenSecondAttempt()
    {
        QFETCH(int, kind);
        QFETCH(QString, needle);
        sim::PtySimulator s(fastModule());
        QVERIFY(s.start());
        s.withDevice([kind](HipnucSimulator &d) {
            auto &f = d.bootloader().faults();
            (kind == 1 ? f.silentDataPacket : kind == 2 ? f.corruptAckDataPacket : f.powerLossDataPacket) = 6;
        });
        const auto img = image("1.7.3", 16 * 1024);
        const QString hex = writeFile(m_dir, QStringLiteral("fw173.hex"), IntelHexWriter::write(img));
        const auto first = cli({"update", s.devicePath(), hex, "--baud", QString::number(kBaud)});
        QCOMPARE(first.code, 1);
        QVERIFY2(first.err.contains(needle), qPrintable(first.err));
        QVERIFY2(first.err.contains(QStringLiteral("imudesk-cli: writing failed")), qPrintable(first.err));
        const auto second = cli({"update", s.devicePath(), hex, "--baud", QString::number(kBaud), "--json"});
        QVERIFY2(second.code == 0, qPrintable(second.err + second.out));
        QCOMPARE(resultLine(second.out).value("resumed").toBool(), true);
        std::string version;
        QVERIFY(flashHolds(s, img, &version));
        QCOMPARE(version, std::string("1.7.3"));
    }

    void nakIsResent()
    {
        sim::PtySimulator s(fastModule());
        QVERIFY(s.start());
        s.withDevice([](HipnucSimulator &d) { d.bootloader().faults().nakDataPacket = 4; });
        const auto img = image("1.7.4", 8 * 1024);
        const QString hex = writeFile(m_dir, QStringLiteral("fw174.hex"), IntelHexWriter::write(img));
        const auto r = cli({"update", s.devicePath(), hex, "--baud", QString::number(kBaud)});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("1 NAK, 1 packets resent")), qPrintable(r.err));
        QVERIFY(flashHolds(s, img));
    }

    void refusedBeforeAnyByte_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("needle");
        const std::string good = IntelHexWriter::write(image("1.7.5", 4096));
        std::string badSum = good;
        const size_t line3 = badSum.find('\n', badSum.find('\n') + 1) + 1; // third line: a data record
        badSum[line3 + 9] = badSum[line3 + 9] == 'A' ? 'B' : 'A';
        FirmwareImage outside = image("1.7.5", 4096);
        outside.startAddress = 0x7F800; // ends at 0x80800, beyond 512 KiB
        QTest::newRow("bad checksum") << QByteArray(badSum.c_str()) << QStringLiteral("line 3: checksum error");
        QTest::newRow("record outside the flash") << QByteArray(IntelHexWriter::write(outside).c_str())
                                                  << QStringLiteral("beyond the end of the flash");
        QTest::newRow("truncated") << QByteArray(good.substr(0, good.size() / 2).c_str()) << QStringLiteral("line");
        QTest::newRow("empty") << QByteArray() << QStringLiteral("empty");
    }
    void refusedBeforeAnyByte()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, needle);
        sim::PtySimulator s(fastModule());
        QVERIFY(s.start());
        const QString path = writeFile(m_dir, QStringLiteral("bad.hex"), content.toStdString());
        const auto r = cli({"update", s.devicePath(), path, "--baud", QString::number(kBaud), "--flash-layout",
                            "0:0x80000:0x8000"});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(needle), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("nothing was sent")), qPrintable(r.err));
        QCOMPARE(s.stats().bytesIn, uint64_t(0));
        QCOMPARE(s.stats().bytesDiscarded, uint64_t(0));
    }

    // A port the user may not open: the update says which group to join and how, in the same
    // words as a session's open (io::SerialTransport), from the link the GUI and the CLI share.
    void refusedPortSaysWhichGroup()
    {
        sim::PtySimulator s(fastModule());
        QVERIFY(s.start());
        const QString pty = s.devicePath();
        QString message;
        if (::geteuid() != 0) {
            QVERIFY(QFile::setPermissions(pty, QFileDevice::Permissions()));
            firmware::SerialByteLink link(pty);
            QVERIFY(!link.open(kBaud, &message));
        } else {
            // Root opens any device: run the CLI as the user nobody on root's pty (mode 0620). The
            // image is in a folder nobody may read, so that only the port can stop the update.
            const QString setpriv = QStandardPaths::findExecutable(QStringLiteral("setpriv"));
            if (setpriv.isEmpty())
                QSKIP("running as root without setpriv: cannot produce a permission error");
            QTemporaryDir shared;
            QVERIFY(shared.isValid());
            QVERIFY(QFile::setPermissions(shared.path(), QFileDevice::ReadOwner | QFileDevice::WriteOwner
                                                             | QFileDevice::ExeOwner | QFileDevice::ReadOther
                                                             | QFileDevice::ExeOther));
            const QString hex = writeFile(shared, QStringLiteral("fw.hex"), IntelHexWriter::write(image("1.7.5", 4096)));
            QVERIFY(QFile::setPermissions(hex, QFileDevice::ReadOwner | QFileDevice::ReadOther));
            const auto r = imudesk::test::runProgram(
                setpriv, {"--reuid=65534", "--regid=65534", "--clear-groups", IMUDESK_CLI_PATH, "update", pty, hex,
                          "--baud", QString::number(kBaud)},
                20000);
            if (r.code == 127 || r.err.contains(QLatin1String("setpriv:")))
                QSKIP(qPrintable(QStringLiteral("setpriv cannot run the CLI as nobody: ") + r.err));
            QCOMPARE(r.code, 1);
            message = r.err;
        }
        QVERIFY2(message.contains(QLatin1String("No permission to open ") + pty), qPrintable(message));
        QVERIFY2(message.contains(QLatin1String("sudo usermod -aG dialout $USER")), qPrintable(message));
        QCOMPARE(s.stats().bytesIn, uint64_t(0));
    }

    void outsideFlashWithoutLayoutRefusedBeforeErasing()
    {
        sim::PtySimulator s(fastModule());
        QVERIFY(s.start());
        FirmwareImage outside = image("1.7.5", 8192);
        outside.startAddress = 0x7F000;
        const QString path = writeFile(m_dir, QStringLiteral("outside.hex"), IntelHexWriter::write(outside));
        const auto r = cli({"update", s.devicePath(), path, "--baud", QString::number(kBaud)});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("refused before erasing")), qPrintable(r.err));
        uint64_t erased = 1;
        s.withDevice([&](HipnucSimulator &d) { erased = d.bootloader().stats().sectorsErased; });
        QCOMPARE(erased, uint64_t(0));
        std::string version;
        QTRY_VERIFY_WITH_TIMEOUT((flashHolds(s, FirmwareImage{}, &version), version == "1.7.1"), 3000);
    }

    void cancelMidWriteIsRecoverable()
    {
        sim::PtySimulator s(fastModule());
        QVERIFY(s.start());
        const auto img = image("1.7.6", 96 * 1024);
        const QString hex = writeFile(m_dir, QStringLiteral("fw176.hex"), IntelHexWriter::write(img));
        QProcess p;
        p.start(QString::fromUtf8(IMUDESK_CLI_PATH), {"update", s.devicePath(), hex, "--baud", QString::number(kBaud), "--json"});
        QVERIFY(p.waitForStarted());
        bool writing = false;
        QString seen;
        QTRY_VERIFY_WITH_TIMEOUT(([&] {
                                     while (p.canReadLine()) {
                                         const auto o = QJsonDocument::fromJson(p.readLine()).object();
                                         if (o.value("event").toString() == QStringLiteral("progress")
                                             && o.value("state").toString() == QStringLiteral("writing")
                                             && o.value("done").toInteger() > 8192)
                                             writing = true;
                                     }
                                     return writing;
                                 }()),
                                 20000);
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(10000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(p.exitCode() == 130, qPrintable(err));
        QVERIFY2(err.contains(QStringLiteral("cancelled while writing")), qPrintable(err));
        std::string state;
        QVERIFY(!flashHolds(s, img, &state));
        QCOMPARE(state, std::string("bootloader"));
        const auto again = cli({"update", s.devicePath(), hex, "--baud", QString::number(kBaud), "--json"});
        QVERIFY2(again.code == 0, qPrintable(again.err));
        QCOMPARE(resultLine(again.out).value("resumed").toBool(), true);
        QVERIFY(flashHolds(s, img, &state));
        QCOMPARE(state, std::string("1.7.6"));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstFirmwareUpdate)
#include "tst_firmware_update.moc"
