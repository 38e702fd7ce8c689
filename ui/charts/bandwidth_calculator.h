#pragma once
// Output-rate and bandwidth calculator: for the chosen messages, rates and baud it shows
// the bytes per second against the link's capacity (frame sizes from the manuals, 10 bits
// per byte), the highest usual rate of each message at that baud (the manuals' table:
// HI91 at 115200 -> 100 Hz) and a warning when the link cannot carry the output.
#include "settings/bandwidth_calculator.h"

#include <QWidget>

#include <map>

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace imudesk::ui {

class BandwidthCalculator : public QWidget {
    Q_OBJECT
public:
    explicit BandwidthCalculator(QWidget *parent = nullptr);

    // Takes the baud, the ONTIME rates and the HI83 map of a device's configuration.
    void setConfiguration(const settings::DeviceConfiguration &config);
    void setBaud(int baud);
    void setRate(protocol::hipnuc::Message m, int hz);
    void setHi83Map(uint32_t map);
    const settings::BandwidthCalculator::Result &result() const { return m_result; }
    QString summaryText() const;
    QString warningText() const;
    QString maxRateText(protocol::hipnuc::Message m) const;

Q_SIGNALS:
    void resultChanged(bool fits);

private:
    void recompute();

    QComboBox *m_baud = nullptr;
    QLineEdit *m_map = nullptr;
    std::map<protocol::hipnuc::Message, QSpinBox *> m_rates;
    std::map<protocol::hipnuc::Message, QLabel *> m_max;
    QLabel *m_summary = nullptr;
    QLabel *m_warning = nullptr;
    settings::BandwidthCalculator::Result m_result;
};

} // namespace imudesk::ui
