#pragma once
// The user's preferences (Edit > Preferences): a typed struct with versioned keys. Only
// main.cpp and the main window open QSettings; everything else is handed this struct.
#include "model/display_units.h"

#include <QString>

class QSettings;

namespace imudesk::ui {

struct Preferences {
    static constexpr const char *kLanguageKey = "prefs/v1/language";          // "", "en", "zh_CN", "zh_TW"
    static constexpr const char *kAccelUnitKey = "prefs/v1/units/acceleration"; // "G", "m/s2"
    static constexpr const char *kRateUnitKey = "prefs/v1/units/angularRate";   // "deg/s", "rad/s"
    static constexpr const char *kFrameKey = "prefs/v1/display/frame";          // "ENU", "NED"
    static constexpr const char *kRefreshKey = "prefs/v1/charts/refreshHz";
    static constexpr const char *kHistoryKey = "prefs/v1/charts/historyMinutes";
    static constexpr const char *kRecordFolderKey = "prefs/v1/recording/folder";
    static constexpr const char *kRecordPatternKey = "prefs/v1/recording/pattern";
    static constexpr const char *kReconnectKey = "prefs/v1/connection/autoReconnect";

    static constexpr int kMinRefreshHz = 10;
    static constexpr int kMaxRefreshHz = 60; // views refresh on a clock of at most 60 Hz
    static constexpr int kMinHistoryMinutes = 1;
    static constexpr int kMaxHistoryMinutes = 10;

    enum class Frame { Enu, Ned };

    QString language;           // empty: follow the system locale
    model::DisplayUnits units;
    Frame frame = Frame::Enu;
    int refreshHz = 33;
    int historyMinutes = 10;
    QString recordingFolder;    // empty: the user's documents folder
    // Expanded by RecordingControls::expandPattern ({product}, {serial}, {date}, {time}).
    QString recordingPattern = QStringLiteral("{product}-{date}-{time}.imucap"); // RecordingControls' default
    bool autoReconnect = true;

    // Values out of range or unknown fall back to the defaults.
    void load(QSettings &settings);
    void save(QSettings &settings) const;
    // The recording folder to use (the documents folder when none was chosen).
    QString effectiveRecordingFolder() const;
    int refreshIntervalMs() const { return 1000 / refreshHz; }
    friend bool operator==(const Preferences &, const Preferences &) = default;
};

} // namespace imudesk::ui
