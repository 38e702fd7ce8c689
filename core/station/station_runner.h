#pragma once
// Runs one test plan on several modules at once (issue 22): one ModuleRunner, and so one
// engine session in its own worker thread, per port, all started together. A module that
// fails or disappears does not stop the others. When a run folder is given, every finished
// module is appended to its summary and gets its PDF report (through reportWriter, which the
// GUI and the CLI supply: PDF needs QtGui, core does not link it). Before anything else, each
// finished module's record (core/results) is committed to the station's results database,
// results.sqlite in the folder the user named (the window's report folder, which holds its run
// folders; the CLI's --report DIR, the run folder itself), and its OpenHTF-shaped JSON is written
// into the run folder (openhtf/<module uuid>.json). With a line database set, an uploader
// forwards the station's database to it in the background (results_uploader.h).
#include "core/station/module_runner.h"
#include "core/results/result_record.h"
#include "core/results/results_store.h"
#include "core/results/results_uploader.h"
#include "core/station/run_folder.h"

#include <QObject>
#include <QStringList>

#include <functional>
#include <memory>
#include <vector>

namespace imudesk::station {

class StationRunner : public QObject {
    Q_OBJECT

public:
    // Writes the PDF of one module at path; false with *error.
    using ReportWriter = std::function<bool(const ModuleResult &, const TestPlan &, const QString &path, QString *error)>;

    struct Summary {
        int passed = 0, failed = 0, running = 0, waiting = 0;
    };

    StationRunner(TestPlan plan, QStringList ports, QObject *parent = nullptr);
    ~StationRunner() override;

    void setBaud(int baud) { m_baud = baud; }
    // The transport each module's session opens its port with (module_runner.h); by default
    // the serial port. For modules started from now on.
    void setTransportFactory(TransportFactory factory) { m_transport = std::move(factory); }
    // Where reports go; empty: nothing is written (the results stay in memory). The results
    // database (results.sqlite) is kept in resultsFolder: the folder the user named. Empty: the
    // run folder's parent, the station window's report folder that holds its run folders
    // (`imudesk-cli station --report DIR` names the run folder itself and keeps it in DIR).
    bool setRunFolder(const QString &dir, QString *error, const QString &resultsFolder = QString());
    const QString &runFolder() const { return m_folder.path(); }
    // The results database (open once a run folder is set); resultsStore().location() says where.
    const results::ResultsStore &resultsStore() const { return m_results; }
    const results::RunRecord &runRecord() const { return m_run; }
    void setReportWriter(ReportWriter writer) { m_writer = std::move(writer); }
    // Who and where, as the records say; by default the host's name and $USER.
    void setStation(const QString &stationId, const QString &operatorName);
    // The line's database (options.outbox is set from the run folder); the uploader starts with
    // the first module and goes on until the runner is destroyed.
    void setLineDatabase(const results::UploaderOptions &options);
    // nullptr without a line database.
    results::ResultsUploader *uploader() const { return m_uploader.get(); }

    // Starts every module not yet run (or all of `only`, by index, again: a re-run).
    void start();
    void rerun(const QList<int> &modules);
    void cancel();
    bool running() const;

    const TestPlan &plan() const { return m_plan; }
    const QStringList &ports() const { return m_ports; }
    int moduleCount() const { return int(m_modules.size()); }
    const ModuleResult &module(int i) const;
    Summary summary() const;
    bool allPassed() const;
    quint64 framesLost() const;
    quint64 frames() const;
    // Problems writing reports, in the order they happened (translated).
    const QStringList &reportErrors() const { return m_reportErrors; }

Q_SIGNALS:
    void moduleChanged(int index);
    void moduleFinished(int index);
    void finished();

private:
    void startModule(int i);
    void onModuleFinished(int i);

    TestPlan m_plan;
    QStringList m_ports;
    int m_baud = 0;
    TransportFactory m_transport;
    RunFolder m_folder;
    bool m_haveFolder = false;
    ReportWriter m_writer;
    results::ResultsStore m_results;
    results::RunRecord m_run;
    std::optional<results::UploaderOptions> m_line;
    std::unique_ptr<results::ResultsUploader> m_uploader;
    std::vector<std::unique_ptr<ModuleRunner>> m_runners;
    std::vector<ModuleResult> m_modules; // the latest result per port
    QStringList m_reportErrors;
    int m_active = 0;
};

} // namespace imudesk::station
