// Tools > Live bridge (ui/bridge/live_bridge_dialog.h) in the window against a simulated HI14:
// started from the window, a Foxglove client gets the tab's device's channels and messages, the
// status bar shows the bridge and its client, a closed tab's channels are withdrawn; a port in
// use is a clear error; another address than loopback is warned about; the choices are
// remembered; the window fits in en and zh_CN.
#include "../common/ui_families.h"
#include "../common/layout_checks.h"
#include "../common/test_main.h"
#include "bridge/bridge_controller.h"
#include "bridge/live_bridge_dialog.h"
#include "workspace/language_switcher.h"
#include "workspace/main_window.h"

#include <QComboBox>
#include <QDir>
#include <QGroupBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTcpServer>
#include <QTest>
#include <QToolButton>
#include <QWebSocket>
#include <QWebSocketHandshakeOptions>

using namespace imudesk;
using namespace imudesk::ui;

namespace {
quint16 freePort()
{
    QTcpServer s;
    s.listen(QHostAddress::LocalHost, 0);
    return s.serverPort();
}
} // namespace

class TstLiveBridgeDialog : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setApplicationVersion(QStringLiteral("test"));
    }

    void bridgesTheTabsDevice()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        w.setErrorPresenter([](const QString &) {});
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        sim::SimOptions options; // HI14, HI91 at 100 Hz
        QString error;
        QVERIFY2(w.openLink(device::LinkRequest::simulatedHipnuc(options, 0), &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(w.currentWorkspace()->link().state(), device::SessionState::Connected, 15000);
        QVERIFY(!w.statusBar()->isVisible());

        LiveBridgeDialog *d = w.openLiveBridge();
        const quint16 port = freePort();
        d->findChild<QSpinBox *>(QStringLiteral("bridgePort"))->setValue(port);
        QVERIFY2(d->startBridge(), qPrintable(d->lastError()));
        QTRY_VERIFY(w.statusBar()->isVisible());
        auto *status = w.statusBar()->findChild<QToolButton *>(QStringLiteral("bridgeStatusButton"));
        QVERIFY(status->text().contains(QStringLiteral("ws://127.0.0.1:%1").arg(port)));

        // A Foxglove client: the device's channels, then its messages once subscribed.
        QWebSocket ws;
        QList<QJsonObject> text;
        int messages = 0;
        connect(&ws, &QWebSocket::textMessageReceived, this,
                [&text](const QString &t) { text << QJsonDocument::fromJson(t.toUtf8()).object(); });
        connect(&ws, &QWebSocket::binaryMessageReceived, this, [&messages](const QByteArray &b) {
            if (!b.isEmpty() && b[0] == 1)
                ++messages;
        });
        QWebSocketHandshakeOptions o;
        o.setSubprotocols({QStringLiteral("foxglove.websocket.v1")});
        ws.open(QUrl(QStringLiteral("ws://127.0.0.1:%1").arg(port)), o);
        QTRY_COMPARE_WITH_TIMEOUT(ws.state(), QAbstractSocket::ConnectedState, 5000);
        int imuChannel = -1;
        QTRY_VERIFY_WITH_TIMEOUT(([&] {
            for (const QJsonObject &m : text)
                if (m.value(QStringLiteral("op")).toString() == QLatin1String("advertise"))
                    for (const QJsonValue &c : m.value(QStringLiteral("channels")).toArray())
                        if (c.toObject().value(QStringLiteral("topic")).toString().endsWith(QLatin1String("/imu")))
                            imuChannel = c.toObject().value(QStringLiteral("id")).toInt();
            return imuChannel > 0;
        }()), 5000);
        QCOMPARE(text.front().value(QStringLiteral("op")).toString(), QStringLiteral("serverInfo"));
        ws.sendTextMessage(QString::fromUtf8(QJsonDocument(QJsonObject{
            {QStringLiteral("op"), QStringLiteral("subscribe")},
            {QStringLiteral("subscriptions"), QJsonArray{QJsonObject{{QStringLiteral("id"), 7}, {QStringLiteral("channelId"), imuChannel}}}}})
                                                 .toJson(QJsonDocument::Compact)));
        QTRY_VERIFY_WITH_TIMEOUT(messages >= 50, 5000); // 100 Hz
        QTRY_VERIFY_WITH_TIMEOUT(status->text().contains(QStringLiteral("clients: 1")), 3000);
        QTRY_VERIFY(d->findChild<QLabel *>(QStringLiteral("bridgeStatus"))->text().contains(QStringLiteral("1 device(s)")));

        // The tab closed: its channels are withdrawn.
        text.clear();
        w.closeWorkspace(0);
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(text.begin(), text.end(), [](const QJsonObject &m) {
            return m.value(QStringLiteral("op")).toString() == QLatin1String("unadvertise");
        }), 5000);

        d->stopBridge();
        QTRY_VERIFY(!w.statusBar()->isVisible());
        QTRY_COMPARE(ws.state(), QAbstractSocket::UnconnectedState);
    }

    void portInUseIsAClearError()
    {
        QTcpServer taken;
        QVERIFY(taken.listen(QHostAddress::LocalHost, 0));
        MainWindow w(imudesk::test::builtInFamilies());
        LiveBridgeDialog *d = w.openLiveBridge();
        d->findChild<QSpinBox *>(QStringLiteral("bridgePort"))->setValue(taken.serverPort());
        QVERIFY(!d->startBridge());
        QVERIFY2(d->lastError().contains(QStringLiteral("Choose another port")), qPrintable(d->lastError()));
        QVERIFY(!w.liveBridge()->bridge().isRunning());
    }

    void otherAddressesAreWarnedAbout()
    {
        MainWindow w(imudesk::test::builtInFamilies());
        LiveBridgeDialog *d = w.openLiveBridge();
        auto *address = d->findChild<QComboBox *>(QStringLiteral("bridgeAddress"));
        auto *warning = d->findChild<QLabel *>(QStringLiteral("bridgeWarning"));
        address->setCurrentIndex(0);
        QVERIFY(!warning->isVisible());
        address->setCurrentIndex(1); // 0.0.0.0
        QVERIFY(warning->isVisible());
        QVERIFY(warning->text().contains(QStringLiteral("no password")));
        address->setEditText(QStringLiteral("::1"));
        QVERIFY(!warning->isVisible());
        address->setEditText(QStringLiteral("not an address"));
        QVERIFY(!d->startBridge());
        QVERIFY(d->lastError().contains(QStringLiteral("not an IP address")));
    }

    void choicesAreRemembered()
    {
        const quint16 port = freePort();
        {
            MainWindow w(imudesk::test::builtInFamilies());
            LiveBridgeDialog *d = w.openLiveBridge();
            d->findChild<QSpinBox *>(QStringLiteral("bridgePort"))->setValue(port);
            d->findChild<QGroupBox *>(QStringLiteral("udpBox"))->setChecked(true);
            d->findChild<QSpinBox *>(QStringLiteral("udpPort"))->setValue(9871);
            QVERIFY2(d->startBridge(), qPrintable(d->lastError()));
            d->stopBridge();
        }
        MainWindow w(imudesk::test::builtInFamilies());
        LiveBridgeDialog *d = w.openLiveBridge();
        QCOMPARE(d->findChild<QSpinBox *>(QStringLiteral("bridgePort"))->value(), int(port));
        QVERIFY(d->findChild<QGroupBox *>(QStringLiteral("udpBox"))->isChecked());
        QCOMPARE(d->findChild<QSpinBox *>(QStringLiteral("udpPort"))->value(), 9871);
    }

    void fitsInEveryLanguage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void fitsInEveryLanguage()
    {
        QFETCH(QString, language);
        LanguageSwitcher switcher;
        QString error;
        QVERIFY2(switcher.setLanguage(language, QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        {
            MainWindow w(imudesk::test::builtInFamilies());
            LiveBridgeDialog *d = w.openLiveBridge();
            d->findChild<QComboBox *>(QStringLiteral("bridgeAddress"))->setCurrentIndex(1); // the warning shown too
            d->findChild<QGroupBox *>(QStringLiteral("udpBox"))->setChecked(true);
            QVERIFY(QTest::qWaitForWindowExposed(d));
            QVERIFY(test::layout::layoutSettled(*d));
            QVERIFY2(d->width() <= 1366 && d->height() <= 700, qPrintable(QStringLiteral("%1x%2").arg(d->width()).arg(d->height())));
            const QStringList problems = test::layout::cutOrOutside(*d);
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
            if (const QString shots = qEnvironmentVariable("IMUDESK_TEST_SHOTS"); !shots.isEmpty())
                d->grab().save(QDir(shots).filePath(QStringLiteral("live-bridge-%1.png").arg(language)));
        }
        QVERIFY(switcher.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error));
    }
};

IMUDESK_TEST_MAIN(TstLiveBridgeDialog)
#include "tst_live_bridge_dialog.moc"
