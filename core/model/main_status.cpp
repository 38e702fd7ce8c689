#include "main_status.h"

#include <QtGlobal>

namespace imudesk::model {

const std::vector<StatusFlagInfo> &MainStatus::definitions()
{
    // Meanings are translated in the ui with the context "imudesk::model::MainStatus".
    static const char *const kManual = QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "HiPNUC manual v1.7.1, 5.9.13");
    static const std::vector<StatusFlagInfo> defs = {
        {WbConv, "WB_CONV", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "Gyro bias estimate not yet converged: keep the module still for 3-5 s to improve heading accuracy."), FlagSeverity::Warning, kManual},
        {MagDist, "MAG_DIST", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "Magnetic disturbance: the field is disturbed, the magnetometer is not calibrated or the hard-iron environment changed; 9-axis heading may be wrong."), FlagSeverity::Warning, kManual},
        {AccSat, "ACC_SAT", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "Accelerometer over range now or within the last 2 s."), FlagSeverity::Warning, kManual},
        {GyrSat, "GYR_SAT", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "Gyroscope over range now or within the last 2 s."), FlagSeverity::Warning, kManual},
        {AttConv, "ATT_CONV", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "Attitude accuracy poor (large AHRS filter covariance): keep still for a moment."), FlagSeverity::Warning, kManual},
        {Static, "STATIC", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "The device detected that it is static."), FlagSeverity::Information,
         QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "the vendor's SDK; the v1.7.1 manual (5.9.13) lists bit 9 as reserved")},
        {MagAiding, "MAG_AIDING", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "The magnetometer takes part in heading (9-axis mode)."), FlagSeverity::Good, kManual},
        {UtcUnsync, "UTC_UNSYNC", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "Not synchronised to UTC: system_time is time since power-up."), FlagSeverity::Information,
         QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "HiPNUC manual v1.7.1, 5.9.13 (named UTC_SYNCED there, but 1 means not synchronised; the SDK calls it UTC_UNSYNC)")},
        {SoutPulse, "SOUT_PULSE", QT_TRANSLATE_NOOP("imudesk::model::MainStatus", "This frame corresponds to a SYNC_OUT pulse."), FlagSeverity::Information, kManual},
    };
    return defs;
}

std::vector<std::string> MainStatus::setFlagNames() const
{
    std::vector<std::string> out;
    for (const auto &d : definitions())
        if ((m_raw >> d.bit) & 1u)
            out.emplace_back(d.name);
    return out;
}

uint16_t MainStatus::undefinedBits() const
{
    uint16_t defined = 0;
    for (const auto &d : definitions())
        defined |= uint16_t(1u << d.bit);
    return m_raw & uint16_t(~defined);
}

} // namespace imudesk::model
