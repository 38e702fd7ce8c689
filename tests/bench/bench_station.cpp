// The production station benchmark (issue 22): the station window offscreen runs a plan of
// about 60 s (identify, firmware check, profile, 20 s static, 25 s Allan, 5 s attitude, save,
// 5 s evidence) first on one simulated HI14 at 115200 baud (the baseline), then on eight at
// once. Prints the wall time of each, their ratio (target ≤ 1.2: the modules run in parallel,
// not in turn), the frames the sessions found missing from the device timestamps (a frame a
// simulator had to drop leaves such a gap too; target 0), and the busy time of the GUI thread during the
// run of eight (target < 30 % of one core), each measured in this run.
//
// usage: bench_station [--modules N] [--plan-seconds S]   (default 8 modules, a 60-s plan)
// Exit code 1 when a target is missed.
#include "sim/pty_simulator.h"
#include "core/station/station_runner.h"
#include "ui/station/station_view.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <ctime>

using namespace imudesk;

namespace {

double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) / 1e9;
}

station::TestPlan benchPlan(double seconds)
{
    // The measuring steps share the plan's length in the proportions 20 : 25 : 5 : 5 of 60 s.
    const double k = seconds / 60.0;
    station::TestPlan plan;
    plan.name = QStringLiteral("bench");
    plan.baseDir = QStringLiteral(IMUDESK_SOURCE_DIR "/docs/examples");
    auto add = [&plan](station::StepKind kind, QVariantMap params = {}) {
        plan.steps.push_back(station::TestPlan::defaultStep(kind, params));
    };
    using station::StepKind;
    add(StepKind::Identify);
    add(StepKind::Firmware, {{QStringLiteral("image"), QString()}});
    add(StepKind::Profile, {{QStringLiteral("profile"), QStringLiteral("station-hi14-profile.json")}});
    add(StepKind::Static, {{QStringLiteral("seconds"), std::max(1.0, 20 * k)}});
    add(StepKind::Allan, {{QStringLiteral("seconds"), std::max(10.0, 25 * k)}});
    add(StepKind::Attitude, {{QStringLiteral("seconds"), std::max(1.0, 5 * k)}});
    add(StepKind::Save);
    add(StepKind::Evidence, {{QStringLiteral("seconds"), std::max(1.0, 5 * k)}});
    return plan;
}

struct RunFigures {
    double seconds = 0;
    double guiCpuSeconds = 0;
    quint64 framesLost = 0;
    quint64 frames = 0;
    int passed = 0, failed = 0;
};

RunFigures runTray(int modules, const station::TestPlan &plan, const QString &reportDir)
{
    RunFigures f;
    ui::StationView view;
    view.setErrorPresenter([](const QString &m) { std::fprintf(stderr, "station: %s\n", qPrintable(m)); });
    view.resize(1366, 768);
    view.show();
    view.setRemembering(false); // the user's report folder and plan stay as they were
    view.setPlan(plan, QString());
    view.setReportFolder(reportDir);
    QString error;
    if (!view.startSimulatedTray(modules, false, &error)) {
        std::fprintf(stderr, "could not start the simulated tray: %s\n", qPrintable(error));
        return f;
    }
    QElapsedTimer clock;
    clock.start();
    const double cpu0 = threadCpuSeconds();
    if (!view.start()) {
        std::fprintf(stderr, "the station did not start\n");
        return f;
    }
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (!view.running())
            loop.quit();
    });
    poll.start(100);
    loop.exec();
    f.seconds = clock.elapsed() / 1000.0;
    f.guiCpuSeconds = threadCpuSeconds() - cpu0;
    const station::StationRunner *runner = view.runner();
    f.framesLost = runner->framesLost();
    f.frames = runner->frames();
    const auto s = runner->summary();
    f.passed = s.passed;
    f.failed = s.failed;
    for (int i = 0; i < runner->moduleCount(); ++i)
        if (runner->module(i).verdict == station::Verdict::Fail)
            std::fprintf(stderr, "  %s failed: %s\n", qPrintable(runner->module(i).port),
                         qPrintable(runner->module(i).failureSummary()));
    view.stopSimulatedTray();
    return f;
}

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    int modules = 8;
    double planSeconds = 60;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QLatin1String("--modules"))
            modules = std::max(1, args[i + 1].toInt());
        if (args[i] == QLatin1String("--plan-seconds"))
            planSeconds = std::max(10.0, args[i + 1].toDouble());
    }
    const station::TestPlan plan = benchPlan(planSeconds);
    QTemporaryDir dir;
    std::printf("bench_station: a %.0f-s plan on simulated HI14 modules at 115200 baud, station window offscreen\n",
                planSeconds);
    const RunFigures one = runTray(1, plan, dir.filePath(QStringLiteral("one")));
    std::printf("  1 module:   %6.1f s  (%d passed, %d failed)\n", one.seconds, one.passed, one.failed);
    const RunFigures many = runTray(modules, plan, dir.filePath(QStringLiteral("many")));
    std::printf("  %d modules: %6.1f s  (%d passed, %d failed)\n", modules, many.seconds, many.passed, many.failed);
    const double ratio = one.seconds > 0 ? many.seconds / one.seconds : 0;
    const double guiPct = many.seconds > 0 ? 100.0 * many.guiCpuSeconds / many.seconds : 0;
    const quint64 lost = many.framesLost + one.framesLost;
    const bool ratioOk = ratio > 0 && ratio <= 1.2;
    const bool lostOk = lost == 0 && many.frames > 0;
    const bool guiOk = guiPct < 30;
    const bool passOk = one.passed == 1 && many.passed == modules;
    std::printf("  time %d modules / 1 module: %.2f (target <= 1.2) %s\n", modules, ratio, ratioOk ? "ok" : "MISSED");
    std::printf("  frames decoded: %llu; lost: %llu (target 0) %s\n", static_cast<unsigned long long>(many.frames),
                static_cast<unsigned long long>(lost), lostOk ? "ok" : "MISSED");
    std::printf("  GUI thread busy during the run of %d: %.1f %% of one core (target < 30 %%) %s\n", modules, guiPct,
                guiOk ? "ok" : "MISSED");
    std::printf("  every module passed: %s\n", passOk ? "yes" : "NO");
    return ratioOk && lostOk && guiOk && passOk ? 0 : 1;
}
