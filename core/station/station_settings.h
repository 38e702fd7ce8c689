#pragma once
// What the station window remembers between sessions (versioned keys, as Preferences).
#include <QSettings>
#include <QString>

namespace imudesk::station {

struct StationSettings {
    static constexpr const char *kReportFolderKey = "station/v1/reportFolder";
    static constexpr const char *kPlanKey = "station/v1/plan";
    static constexpr const char *kLineDatabaseKey = "station/v1/lineDatabase";
    static constexpr const char *kArtifactFolderKey = "station/v1/artifactFolder";

    QString reportFolder; // empty: defaultReportFolder()
    QString planPath;     // the plan opened last; empty: none
    QString lineDatabase;   // the line's PostgreSQL URL (ui/station/line_database_dialog.h); empty: none
    QString artifactFolder; // where the uploader copies reports and recordings; empty: they stay here

    void load(QSettings &settings);
    void save(QSettings &settings) const;
    // <Documents>/ImuDesk/station
    static QString defaultReportFolder();
    // What Tools > Results reads: the line database when set, else <report folder>/results.sqlite.
    QString resultsDatabase() const;
};

} // namespace imudesk::station
