#include "core/station/station_settings.h"

#include "core/results/results_store.h"

#include <QDir>
#include <QStandardPaths>

namespace imudesk::station {

void StationSettings::load(QSettings &settings)
{
    reportFolder = settings.value(QLatin1String(kReportFolderKey)).toString();
    planPath = settings.value(QLatin1String(kPlanKey)).toString();
    lineDatabase = settings.value(QLatin1String(kLineDatabaseKey)).toString();
    artifactFolder = settings.value(QLatin1String(kArtifactFolderKey)).toString();
}

void StationSettings::save(QSettings &settings) const
{
    settings.setValue(QLatin1String(kReportFolderKey), reportFolder);
    settings.setValue(QLatin1String(kPlanKey), planPath);
    settings.setValue(QLatin1String(kLineDatabaseKey), lineDatabase);
    settings.setValue(QLatin1String(kArtifactFolderKey), artifactFolder);
}

QString StationSettings::defaultReportFolder()
{
    return QDir(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation))
        .filePath(QStringLiteral("ImuDesk/station"));
}

QString StationSettings::resultsDatabase() const
{
    if (!lineDatabase.isEmpty())
        return lineDatabase;
    return QDir(reportFolder.isEmpty() ? defaultReportFolder() : reportFolder).filePath(QLatin1String(results::ResultsStore::kFileName));
}

} // namespace imudesk::station
