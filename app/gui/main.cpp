// ImuDesk GUI: command line, language, settings, main window.
#include "workspace/device_workspace.h"
#include "workspace/language_switcher.h"
#include "families/built_in_families.h"
#include "links/serial_family.h"
#include "workspace/family_ui.h"
#include "recording/twist_align_dialog.h"
#include "workspace/tool_actions.h"
#include "workspace/main_window.h"
#include "bridge/bridge_controller.h"
#include "model/device_identity.h"
#include "sim/hipnuc_simulator.h"
#include "sim/motion_model.h"
#include "ui/discovery/find_devices_dialog.h"
#include "ui/station/station_view.h"
#include "workspace/preferences.h"
#include "workspace/window_settings.h"

#include <QApplication>
#include <QDockWidget>
#include <QIcon>
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QPointer>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <QStringList>

#include <algorithm>
#include <map>
#include <cstdio>

using imudesk::ui::LanguageSwitcher;
using imudesk::ui::MainWindow;
using imudesk::ui::Preferences;
using imudesk::ui::WindowSettings;

namespace {

int usageError(const QString &message)
{
    std::fprintf(stderr, "imudesk: %s\n", qPrintable(message));
    return 2;
}

// "--simulate=HI12" -> "--simulate HI12": the model is an optional positional argument.
QStringList splitSimulateValue(const QStringList &args)
{
    QStringList out;
    for (const QString &a : args) {
        if (a.startsWith(QLatin1String("--simulate="))) {
            out << QStringLiteral("--simulate") << a.mid(11);
        } else {
            out << a;
        }
    }
    return out;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("ImuDesk"));
    QCoreApplication::setApplicationName(QStringLiteral("ImuDesk"));
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.imudesk.ImuDesk"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/imudesk.svg")));
    QCoreApplication::setApplicationVersion(QStringLiteral(IMUDESK_VERSION));

    // Preferences, then the language (--lang, else the preferences' choice, else the system's)
    // first, so that the help text and any message are translated.
    Preferences prefs;
    {
        QSettings store;
        prefs.load(store);
    }
    const QStringList args = splitSimulateValue(QCoreApplication::arguments());
    QString lang = prefs.language.isEmpty() ? LanguageSwitcher::fromLocale(QLocale::system()) : prefs.language;
    for (qsizetype i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--lang") && i + 1 < args.size())
            lang = args[i + 1];
        else if (args[i].startsWith(QLatin1String("--lang=")))
            lang = args[i].mid(7);
    }
    LanguageSwitcher language;
    QString langError;
    if (!language.setLanguage(lang, QString::fromLatin1(LanguageSwitcher::kResourceDir), &langError))
        return usageError(langError);

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QCoreApplication::translate("main", "ImuDesk: a bench tool for HiPNUC IMU modules."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption langOption(
        QStringLiteral("lang"),
        QCoreApplication::translate("main", "User interface language: zh_CN, zh_TW or en (default: the system's)."),
        QStringLiteral("language"));
    const QCommandLineOption simulateOption(
        QStringLiteral("simulate"),
        QCoreApplication::translate("main", "Start connected to a simulated device (model MODEL, default HI14) "
                                            "that streams HI91 at 100 Hz."));
    const QCommandLineOption firmwareOption(
        QStringLiteral("firmware"),
        QCoreApplication::translate("main", "Firmware of the simulated device: 1.7.1 or 1.6.6 (default 1.7.1)."),
        QStringLiteral("version"), QStringLiteral("1.7.1"));
    const QCommandLineOption motionOption(
        QStringLiteral("motion"),
        QCoreApplication::translate("main", "Motion of the simulated device: static, spin or tumble (default static)."),
        QStringLiteral("motion"), QStringLiteral("static"));
    const QCommandLineOption portOption(
        QStringLiteral("port"), QCoreApplication::translate("main", "Start connected to this serial port."),
        QStringLiteral("path"));
    const QCommandLineOption baudOption(
        QStringLiteral("baud"),
        QCoreApplication::translate("main", "Baud rate for --port or --simulate (default: detect automatically)."),
        QStringLiteral("rate"));
    const QCommandLineOption demoOption(
        QStringLiteral("demo"),
        QCoreApplication::translate("main", "Start connected to a simulated HI14 (firmware 1.7.1) that tumbles slowly "
                                            "through every orientation."));
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("main", "Save the main window to this PNG file and quit (see --after)."),
        QStringLiteral("file"));
    const QCommandLineOption afterOption(
        QStringLiteral("after"),
        QCoreApplication::translate("main", "Seconds to wait before --screenshot (default 3)."),
        QStringLiteral("seconds"), QStringLiteral("3"));
    const QCommandLineOption linkOption(
        QStringLiteral("link"),
        QCoreApplication::translate("main", "Start connected to another simulated device: hec495 (compass on serial), "
                                            "modbus (HI14 over Modbus RTU), can (HI14 J1939 on virtualcan) or "
                                            "canopen (HI14 CANopen on virtualcan); or replay a capture file, or a recorded session (its session.json or folder)."),
        QStringLiteral("device|file"));
    const QCommandLineOption dockOption(
        QStringLiteral("dock"),
        QCoreApplication::translate("main", "Bring this panel to the front: configuration, recording, console, raw, "
                                            "commands, can (the CAN configuration) or sync (the clocks)."),
        QStringLiteral("panel"));
    const QCommandLineOption alignOption(
        QStringLiteral("align"),
        QCoreApplication::translate("main", "Open Twist to align on a recorded session's FOLDER and find the devices' "
                                            "offsets. With --screenshot the dialog is saved."),
        QStringLiteral("folder"));
    const QCommandLineOption stationOption(
        QStringLiteral("station"),
        QCoreApplication::translate("main", "Open the production station window; with PLAN (a test plan file), "
                                            "load that plan. With --screenshot the station window is saved."));
    const QCommandLineOption stationDemoOption(
        QStringLiteral("station-demo"),
        QCoreApplication::translate("main", "Open the production station with a simulated tray of 8 HI14 modules "
                                            "(one with a noisy gyro, one mounted wrongly, one with firmware 1.6.6) "
                                            "and run PLAN on it; without PLAN the built-in example plan, its "
                                            "firmware step without an image (the old module fails it) and its "
                                            "profile step off."));
    const QCommandLineOption bridgeOption(
        QStringLiteral("bridge"),
        QCoreApplication::translate("main", "Start the live bridge (Tools > Live bridge) on ADDR:PORT, e.g. "
                                            "127.0.0.1:8765: the connected devices to Foxglove, Lichtblick and PlotJuggler."),
        QStringLiteral("ADDR:PORT"));
    const QCommandLineOption findOption(
        QStringLiteral("find-devices"),
        QCoreApplication::translate("main", "Open Device > Find devices… at start (a first start without a device "
                                            "to open does so anyway)."));
    const QCommandLineOption findBenchOption(
        QStringLiteral("find-devices-bench"),
        QCoreApplication::translate("main", "Open Device > Find devices… on a simulated bench (six devices on four "
                                            "ports and a virtualcan bus, two of them sharing a node ID) and sweep it."));
    parser.addOptions({langOption, simulateOption, firmwareOption, motionOption, portOption, baudOption, demoOption,
                       screenshotOption, afterOption, linkOption, dockOption, alignOption, stationOption, stationDemoOption,
                       bridgeOption, findOption, findBenchOption});
    parser.addPositionalArgument(QStringLiteral("MODEL"),
                                 QCoreApplication::translate("main", "Model to simulate with --simulate (default HI14)."),
                                 QStringLiteral("[MODEL]"));
    parser.addPositionalArgument(QStringLiteral("PLAN"),
                                 QCoreApplication::translate("main", "Test plan for --station or --station-demo."),
                                 QStringLiteral("[PLAN]"));
    parser.process(args);

    const QStringList positional = parser.positionalArguments();
    const bool demo = parser.isSet(demoOption);
    const bool simulate = parser.isSet(simulateOption) || demo;
    const bool stationDemo = parser.isSet(stationDemoOption);
    const bool station = parser.isSet(stationOption) || stationDemo;
    if (!positional.isEmpty() && simulate && station)
        return usageError(QCoreApplication::translate("main", "Give either a model (--simulate) or a plan (--station), "
                                                              "not both."));
    if (positional.size() > 1 || (!positional.isEmpty() && !simulate && !station))
        return usageError(QCoreApplication::translate("main", "A model name is only accepted after --simulate."));
    const QString stationPlan = station ? positional.value(0) : QString();
    double screenshotAfter = 3;
    if (parser.isSet(afterOption)) {
        bool ok = false;
        screenshotAfter = parser.value(afterOption).toDouble(&ok);
        if (!ok || screenshotAfter < 0 || screenshotAfter > 3600)
            return usageError(QCoreApplication::translate("main", "--after needs a number of seconds from 0 to 3600."));
    }
    if (simulate && parser.isSet(portOption))
        return usageError(QCoreApplication::translate("main", "Use either --simulate or --port, not both."));

    int baud = 0;
    if (parser.isSet(baudOption) && parser.value(baudOption) != QLatin1String("auto")) {
        bool ok = false;
        baud = parser.value(baudOption).toInt(&ok);
        const auto &rates = imudesk::device::serialDetectionBauds();
        if (!ok || std::find(rates.begin(), rates.end(), baud) == rates.end()) {
            QStringList names;
            for (int r : rates)
                names << QString::number(r);
            return usageError(QCoreApplication::translate("main", "Unsupported baud rate \"%1\"; use auto or one of: %2.")
                                  .arg(parser.value(baudOption), names.join(QStringLiteral(", "))));
        }
    }

    imudesk::sim::SimOptions simOptions;
    simOptions.model = positional.isEmpty() || !simulate ? std::string("HI14") : positional.first().toUpper().toStdString();
    simOptions.firmware = parser.value(firmwareOption).toStdString();
    if (!imudesk::model::FirmwareVersion::parse(simOptions.firmware))
        return usageError(QCoreApplication::translate("main", "Invalid firmware version \"%1\"; use e.g. 1.7.1 or 1.6.6.")
                              .arg(parser.value(firmwareOption)));
    if (demo && !parser.isSet(motionOption))
        simOptions.motion = imudesk::sim::Motion::Tumble;
    else if (!imudesk::sim::parseMotion(parser.value(motionOption).toStdString(), simOptions.motion))
        return usageError(QCoreApplication::translate("main", "Unknown motion \"%1\"; use static, spin or tumble.")
                              .arg(parser.value(motionOption)));

    WindowSettings settings;
    {
        QSettings store;
        settings.load(store);
    }
    // The device families the window shows, each with its docks and tools: registered once, here.
    imudesk::ui::FamilyUiRegistry families;
    imudesk::ui::registerBuiltInFamilies(families);
    MainWindow window(families, settings);
    window.setPreferences(prefs);
    QObject::connect(&window, &MainWindow::preferencesChanged, &window, [](const Preferences &changed) {
        QSettings store;
        changed.save(store);
    });
    window.setSimulatedMotion(simOptions.motion);
    window.showAsSaved();

    if (simulate) {
        QString error;
        if (!window.openLink(imudesk::device::LinkRequest::simulatedHipnuc(simOptions, baud), &error))
            QMessageBox::warning(&window, QCoreApplication::translate("main", "ImuDesk"), error);
    } else if (parser.isSet(portOption)) {
        window.connectPort(parser.value(portOption), baud);
    } else if (parser.isSet(linkOption)) {
        const QString link = parser.value(linkOption);
        QString error;
        bool ok = true;
        if (link == QLatin1String("hec495")) {
            ok = window.openLink(imudesk::device::LinkRequest::simulatedHec495(simOptions.motion), &error);
        } else if (link == QLatin1String("modbus")) {
            imudesk::device::LinkRequest request = imudesk::device::LinkRequest::modbusDevice({});
            request.simulate = true;
            request.motion = simOptions.motion;
            ok = window.openLink(request, &error);
        } else if (link == QLatin1String("can") || link == QLatin1String("canopen")) {
            imudesk::device::CanSessionOptions o;
            o.protocol = link == QLatin1String("can") ? imudesk::protocol::can::CanProtocol::J1939
                                                      : imudesk::protocol::can::CanProtocol::CanOpen;
            imudesk::device::LinkRequest request = imudesk::device::LinkRequest::canBus(o);
            request.simulate = true;
            request.motion = simOptions.motion;
            ok = window.openLink(request, &error);
        } else {
            ok = window.tools()->openCapture(link);
        }
        if (!ok && !error.isEmpty())
            QMessageBox::warning(&window, QCoreApplication::translate("main", "ImuDesk"), error);
    }
    // Device > Find devices…: asked for, or the first thing a first start offers when nothing
    // else was asked for (remembered: offered once).
    {
        QSettings store;
        const bool nothingAsked = !simulate && !parser.isSet(portOption) && !parser.isSet(linkOption) && !station
            && !parser.isSet(screenshotOption);
        const bool firstStart = nothingAsked && !store.value(QStringLiteral("findDevices/offered")).toBool();
        if (parser.isSet(findOption) || parser.isSet(findBenchOption) || firstStart) {
            store.setValue(QStringLiteral("findDevices/offered"), true);
            window.tools()->findDevicesAction()->trigger();
            if (parser.isSet(findBenchOption))
                if (auto *find = window.findChild<imudesk::ui::FindDevicesDialog *>())
                    if (find->useSimulatedBench(true))
                        find->start();
        }
    }
    if (parser.isSet(dockOption)) {
        static const std::map<QString, QString> docks = {
            {QStringLiteral("configuration"), QStringLiteral("configDock")},
            {QStringLiteral("recording"), QStringLiteral("recordingDock")},
            {QStringLiteral("console"), QStringLiteral("consoleDock")},
            {QStringLiteral("raw"), QStringLiteral("rawBytesDock")},
            {QStringLiteral("commands"), QStringLiteral("commandLogDock")},
            {QStringLiteral("can"), QStringLiteral("canConfigDock")},
            {QStringLiteral("sync"), QStringLiteral("syncDock")},
        };
        const auto it = docks.find(parser.value(dockOption));
        if (it == docks.end())
            return usageError(QCoreApplication::translate("main", "Unknown panel \"%1\"; use configuration, recording, "
                                                                  "console, raw, commands, can or sync.")
                                  .arg(parser.value(dockOption)));
        if (it->first == QLatin1String("configuration")) {
            // The Configure layout: the settings table gets the right column's height.
            window.applyLayoutPreset(imudesk::ui::DeviceWorkspace::LayoutPreset::Configure);
        } else if (auto *dock = window.currentWorkspace()->findChild<QDockWidget *>(it->second)) {
            dock->show();
            dock->raise();
        }
    }

    // The production station: its window, the plan given, and for the demo a simulated tray
    // that starts testing at once. A screenshot run writes its reports into a folder of its own
    // and leaves the remembered plan and report folder alone.
    QPointer<imudesk::ui::StationView> stationView;
    QTemporaryDir automationReports;
    if (station) {
        stationView = window.openStation();
        if (parser.isSet(screenshotOption)) {
            stationView->setRemembering(false);
            stationView->setReportFolder(automationReports.path());
        }
        if (!stationPlan.isEmpty())
            stationView->openPlan(stationPlan); // a plan that does not load is reported in the window
        else if (stationDemo)
            stationView->setPlan(imudesk::ui::StationView::demoPlan(), QString());
        if (stationDemo) {
            QString error;
            if (!stationView->startSimulatedTray(imudesk::ui::StationView::kDemoTraySize, true, &error))
                QMessageBox::warning(stationView, QCoreApplication::translate("main", "ImuDesk"), error);
            else if (stationView->hasPlan())
                stationView->start();
        }
    }

    QPointer<imudesk::ui::TwistAlignDialog> alignDialog;
    if (parser.isSet(alignOption)) {
        alignDialog = new imudesk::ui::TwistAlignDialog(parser.value(alignOption), &window);
        alignDialog->setAttribute(Qt::WA_DeleteOnClose);
        alignDialog->show();
        alignDialog->findOffsets();
    }

    if (parser.isSet(bridgeOption)) {
        imudesk::bridge::BridgeOptions o;
        QString error;
        imudesk::bridge::LiveBridge::parseHostPort(parser.value(bridgeOption), &o.address, &o.port, &error);
        if (error.isEmpty())
            window.liveBridge()->start(o, &error);
        if (!error.isEmpty())
            std::fprintf(stderr, "imudesk: the live bridge did not start: %s\n", qPrintable(error));
        else
            std::fprintf(stderr, "imudesk: live bridge on %s\n", qPrintable(window.liveBridge()->bridge().url()));
    }

    int screenshotRc = 0;
    if (parser.isSet(screenshotOption)) {
        const QString path = parser.value(screenshotOption);
        QTimer::singleShot(int(screenshotAfter * 1000), &window,
                           [&window, &screenshotRc, &stationView, &alignDialog, station, path] {
            QString error;
            // With --station the station window is the picture (while it is open), with --align the dialog.
            bool saved = false;
            if (alignDialog) {
                saved = alignDialog->grab().save(path);
                if (!saved)
                    error = QStringLiteral("cannot write %1").arg(path);
            } else {
                saved = station && stationView ? stationView->saveScreenshot(path, &error)
                                               : window.saveScreenshot(path, &error);
            }
            if (!saved) {
                std::fprintf(stderr, "imudesk: %s\n", qPrintable(error));
                screenshotRc = 1;
            }
            QApplication::quit();
        });
    }

    const int rc = QApplication::exec();
    // Only a person's session is remembered: a --screenshot run or any other automation (the
    // offscreen or minimal platform, IMUDESK_NO_SAVE_LAYOUT set) leaves the user's layout as
    // it was, or the next start would open with the automation's window size and docks.
    const QString platform = QGuiApplication::platformName();
    const bool automation = parser.isSet(screenshotOption) || platform == QLatin1String("offscreen")
        || platform == QLatin1String("minimal") || qEnvironmentVariableIsSet("IMUDESK_NO_SAVE_LAYOUT");
    if (!automation) {
        QSettings store;
        window.windowSettings().save(store);
    }
    return rc != 0 ? rc : screenshotRc;
}
