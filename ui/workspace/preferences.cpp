#include "workspace/preferences.h"

#include <QSettings>
#include <QStandardPaths>

#include <algorithm>

namespace imudesk::ui {

void Preferences::load(QSettings &settings)
{
    const Preferences defaults;
    *this = defaults;
    const QString lang = settings.value(QLatin1String(kLanguageKey)).toString();
    if (lang.isEmpty() || lang == QLatin1String("en") || lang == QLatin1String("zh_CN") || lang == QLatin1String("zh_TW"))
        language = lang;
    units.accel = settings.value(QLatin1String(kAccelUnitKey)).toString() == QLatin1String("m/s2")
                      ? model::AccelUnit::MetresPerSecondSquared
                      : model::AccelUnit::G;
    units.rate = settings.value(QLatin1String(kRateUnitKey)).toString() == QLatin1String("rad/s")
                     ? model::RateUnit::RadiansPerSecond
                     : model::RateUnit::DegreesPerSecond;
    frame = settings.value(QLatin1String(kFrameKey)).toString() == QLatin1String("NED") ? Frame::Ned : Frame::Enu;
    bool ok = false;
    const int hz = settings.value(QLatin1String(kRefreshKey)).toInt(&ok);
    if (ok && hz >= kMinRefreshHz && hz <= kMaxRefreshHz)
        refreshHz = hz;
    const int minutes = settings.value(QLatin1String(kHistoryKey)).toInt(&ok);
    if (ok && minutes >= kMinHistoryMinutes && minutes <= kMaxHistoryMinutes)
        historyMinutes = minutes;
    recordingFolder = settings.value(QLatin1String(kRecordFolderKey)).toString();
    const QString pattern = settings.value(QLatin1String(kRecordPatternKey)).toString();
    if (!pattern.trimmed().isEmpty())
        recordingPattern = pattern;
    autoReconnect = settings.value(QLatin1String(kReconnectKey), defaults.autoReconnect).toBool();
}

void Preferences::save(QSettings &settings) const
{
    settings.setValue(QLatin1String(kLanguageKey), language);
    settings.setValue(QLatin1String(kAccelUnitKey),
                      units.accel == model::AccelUnit::G ? QStringLiteral("G") : QStringLiteral("m/s2"));
    settings.setValue(QLatin1String(kRateUnitKey), units.rate == model::RateUnit::DegreesPerSecond
                                                       ? QStringLiteral("deg/s")
                                                       : QStringLiteral("rad/s"));
    settings.setValue(QLatin1String(kFrameKey), frame == Frame::Enu ? QStringLiteral("ENU") : QStringLiteral("NED"));
    settings.setValue(QLatin1String(kRefreshKey), refreshHz);
    settings.setValue(QLatin1String(kHistoryKey), historyMinutes);
    settings.setValue(QLatin1String(kRecordFolderKey), recordingFolder);
    settings.setValue(QLatin1String(kRecordPatternKey), recordingPattern);
    settings.setValue(QLatin1String(kReconnectKey), autoReconnect);
}

QString Preferences::effectiveRecordingFolder() const
{
    if (!recordingFolder.isEmpty())
        return recordingFolder;
    return QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
}

} // namespace imudesk::ui
