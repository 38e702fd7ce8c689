#pragma once
// Tools > Results (issue 38): the results database the station writes, searched and summed up.
// It reads the line's database when the station has one (StationSettings::lineDatabase), else
// the station's own file (<report folder>/results.sqlite), says which, and opens another SQLite
// file on request (Open…). A filter row (part of a serial number, plan, station, from and to
// dates; Search or Enter) drives three tabs: Modules (the modules found, and below them every
// attempt of the selected serial number with its steps, measurements and files; the PDF opens
// in the desktop's viewer), Yield (per firmware and fixture slot, for the chosen plan) and
// Trend (one measurement over time with its limits, marginal band and Cpk).
//
// Nothing here blocks: every read runs in a ResultsQuery's thread with its own connection, a
// busy bar shows while one is under way, and an answer that a newer question made stale is
// dropped. A database that cannot be read (a server that is down, a file that is not one) is
// said in a line in the window with what to do; the window keeps working, and Search tries
// again. Not modal, one instance (MainWindow::openResults); its size and place are remembered.
#include "core/results/results_store.h"

#include <QWidget>

#include <functional>

QT_BEGIN_NAMESPACE
class QCheckBox;
class QComboBox;
class QDateEdit;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSettings;
class QSplitter;
class QTabWidget;
class QTableView;
class QUrl;
QT_END_NAMESPACE

namespace imudesk::results {
class ResultsQuery;
}

namespace imudesk::ui {

using results::ResultsQuery;

class ElidedLabel;
class ModuleHistoryView;
class ModuleTableModel;
class TrendView;
class YieldView;

// What the results window remembers (versioned keys, as StationSettings).
struct ResultsWindowSettings {
    static constexpr const char *kGeometryKey = "results/v1/geometry";
    static constexpr const char *kSplitterKey = "results/v1/modulesSplitter";

    QByteArray geometry, splitter;

    void load(QSettings &settings);
    void save(QSettings &settings) const;
};

class ResultsWindow : public QWidget {
    Q_OBJECT

public:
    // Opens a file in the desktop's application for it; false when none could.
    using UrlOpener = std::function<bool(const QUrl &url)>;
    enum Tab { ModulesTab, YieldTab, TrendTab };

    explicit ResultsWindow(QWidget *parent = nullptr);
    ~ResultsWindow() override;

    // The station's database as its saved settings name it: the line database when one is
    // set, else <report folder>/results.sqlite.
    static QString stationDatabase();
    // Reads from location (a server URL or an SQLite file) from now on, and searches it.
    // chosen: the user picked the file (Open…), rather than the station's settings naming it.
    void openLocation(const QString &location, bool chosen = false);
    const QString &location() const { return m_location; }
    // Open…: a file dialog for an SQLite file.
    void chooseFile();

    // Search (or Enter): the modules the filter row describes, and the yield and trend of its plan.
    void search();
    results::ResultsStore::Filter filter() const;
    // A read is under way.
    bool busy() const;
    // The problem shown in the window; empty when there is none.
    QString problem() const;

    ModuleTableModel *modulesModel() const { return m_model; }
    QTableView *modulesTable() const { return m_table; }
    ModuleHistoryView *history() const { return m_history; }
    YieldView *yieldView() const { return m_yield; }
    TrendView *trendView() const { return m_trend; }
    QTabWidget *tabs() const { return m_tabs; }

    // Replaces QDesktopServices::openUrl (tests record the URLs instead).
    void setUrlOpener(UrlOpener opener) { m_urlOpener = std::move(opener); }
    // Whether size and place are remembered (off for tests and screenshots).
    void setRemembering(bool on) { m_remember = on; }
    // Saves the window as a PNG; false with a reason when it cannot be written.
    bool saveScreenshot(const QString &path, QString *error = nullptr);

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    enum Channel { OpenChannel, ListsChannel, SearchChannel, HistoryChannel, YieldChannel, MeasurementsChannel, TrendChannel };

    void retranslateUi();
    void updateSource();
    void updateStatus();
    void showProblem(const QString &text);
    // A read failed: the error, and what to do about it.
    void readFailed(const QString &error);
    void refreshLists();
    void refreshYield();
    void refreshMeasurements();
    void refreshTrend();
    void showSelectedHistory();
    void openArtifact(const QString &location);
    void fillCombo(QComboBox *combo, const QStringList &values);
    QString chosenPlan() const;
    QDateTime fromTime() const;
    QDateTime toTime() const;

    ResultsQuery *m_query = nullptr;
    QString m_location;
    bool m_chosen = false;
    bool m_remember = true;
    int m_found = -1; // modules of the last search; -1 before one
    bool m_limited = false;
    QString m_problem;
    UrlOpener m_urlOpener;

    QLabel *m_sourceTitle = nullptr;
    ElidedLabel *m_source = nullptr;
    QPushButton *m_openFile = nullptr;
    QWidget *m_filterRow = nullptr;
    QLabel *m_serialTitle = nullptr;
    QLineEdit *m_serial = nullptr;
    QLabel *m_planTitle = nullptr;
    QComboBox *m_plan = nullptr;
    QLabel *m_stationTitle = nullptr;
    QComboBox *m_station = nullptr;
    QCheckBox *m_fromCheck = nullptr;
    QDateEdit *m_from = nullptr;
    QCheckBox *m_toCheck = nullptr;
    QDateEdit *m_to = nullptr;
    QPushButton *m_search = nullptr;
    QProgressBar *m_busy = nullptr;
    ElidedLabel *m_status = nullptr;
    QLabel *m_problemLabel = nullptr;
    QTabWidget *m_tabs = nullptr;
    QSplitter *m_modulesSplit = nullptr;
    QTableView *m_table = nullptr;
    ModuleTableModel *m_model = nullptr;
    ModuleHistoryView *m_history = nullptr;
    YieldView *m_yield = nullptr;
    TrendView *m_trend = nullptr;
};

} // namespace imudesk::ui
