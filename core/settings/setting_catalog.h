#pragma once
// Every documented HiPNUC setting and action (v1.7.1 chapters 2-4, v1.6.6 chapter 2),
// and the rules for their values. A value travels as canonical text, the same for the
// CLI (KEY=VALUE), profiles (JSON) and the settings model:
//   SERIAL.BAUD     "115200"
//   LOG             "ENABLE" | "DISABLE"
//   LOG.<MSG>       "OFF" | "ONMARK" | a period in seconds "0.01" (0.001 .. 1)
//   LOG.HI83.MAP    "0x000000FF"
//   ATT.MODE        "0" | "1" | "4";  IMU.COORD "0" | "4";  IMU_EN_MCAL "0" | "1"
//   IMU.URFR        one of the 24 codes "24", "205" ... or, for a v1.6.6 matrix that is
//                   none of them, its nine numbers C00..C22 "0.6,0.8,0,..." (X_B = C * X_U)
//   PMUX1..3        "IO1" .. "IO5" (v1.6.6: IO9);  PMUX2.DIV "1" .. "1000"
#include "model/device_identity.h"
#include "settings/setting_definition.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <QStringList>

#include <optional>
#include <string>
#include <vector>

namespace imudesk::settings {

class SettingCatalog {
    Q_DECLARE_TR_FUNCTIONS(SettingCatalog)

public:
    struct Availability {
        bool available = true;
        QString reason; // why not, for a tooltip or an error
    };
    struct Choice {
        QString value;
        QString label;
    };

    static const std::vector<SettingDefinition> &settings();
    static const std::vector<ActionDefinition> &actions();
    // Case-insensitive; nullptr when unknown.
    static const SettingDefinition *find(const QString &key);
    static const ActionDefinition *findAction(const QString &key);
    // All keys, for messages ("known keys: ...").
    static QStringList keys();

    // The feature table of v1.7.1 chapter 3. An unknown family is given every feature.
    static bool hasFeature(Feature f, model::ProductFamily family);
    static Availability availability(const SettingDefinition &d, const model::DeviceIdentity &id);
    static Availability availability(const ActionDefinition &a, const model::DeviceIdentity &id);

    // The canonical text of a value typed by a user or read from a profile; std::nullopt
    // and *error when refused. With an identity the device's range applies (its edition's
    // baud list, PMUX pins, ATT MODE 4), without one any edition's range.
    static std::optional<QString> normalize(const SettingDefinition &d, const QString &input,
                                            const model::DeviceIdentity *id, QString *error);
    // The canonical text of a LOG COMCONFIG value ("ONTIME 0.01" -> "0.01"); std::nullopt
    // when the device's text cannot be understood.
    static std::optional<QString> fromComConfig(const SettingDefinition &d, const std::string &value);
    // The command(s) that set a canonical value on this device; empty and *error when the
    // device cannot take it.
    static std::vector<protocol::hipnuc::Command> commands(const SettingDefinition &d, const QString &canonical,
                                                           const model::DeviceIdentity &id, QString *error);
    // The command of an action. CONFIG YAW takes "MODE,DEG" (e.g. "1,16"); others take nothing.
    static std::optional<protocol::hipnuc::Command> actionCommand(const ActionDefinition &a, const QString &argument,
                                                                  QString *error);

    // Human-readable value ("1 (AHRS, 9-axis)", "100 Hz (0.01 s)").
    static QString valueText(const SettingDefinition &d, const QString &canonical);
    // The values a device can take, for a combo box (empty for free-form kinds).
    static QList<Choice> choices(const SettingDefinition &d, const model::DeviceIdentity &id);
    static QString label(const SettingDefinition &d);
    static QString description(const SettingDefinition &d);
    static QString label(const ActionDefinition &a);
    static QString conditions(const ActionDefinition &a);
    // "after SAVECONFIG and a reset", ...
    static QString persistenceText(Persistence p);
    // "LOG COMCONFIG: ATT_MODE"
    static QString readBackText(const SettingDefinition &d);
    static QString featureText(Feature f);
};

} // namespace imudesk::settings
