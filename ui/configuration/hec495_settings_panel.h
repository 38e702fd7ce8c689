#pragma once
// Settings of a Witlink HEC495, bound to its Hec495Session: magnetic declination (read and
// set), baud, auto-output rate (question/answer or 5-100 Hz) and content, module address (set,
// and queried with 2.17), save settings and factory reset; and the single reads of pitch,
// roll, heading or all three (manual 2.1-2.4), whose answer shows in the status line. One request at a time: the controls are disabled while
// one is pending and the result (success, the module's failure, a timeout) shows in the
// status line. The session follows baud and address changes by itself; the panel shows them.
// Settings are lost at power-off unless saved (the manual's 2.18), which the panel says.
#include "device/hec495_result.h"

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace imudesk::device {
class Hec495Session;
}

namespace imudesk::ui {

class Hec495SettingsPanel : public QWidget {
    Q_OBJECT
public:
    explicit Hec495SettingsPanel(device::Hec495Session *session, QWidget *parent = nullptr);

    // Ask before a factory reset (on by default; tests turn it off).
    void setConfirmReset(bool on) { m_confirmReset = on; }
    bool busy() const { return m_pending != 0; }
    QString statusText() const;

    // The controls, for tests and the integrator's layout.
    QDoubleSpinBox *declinationBox() const { return m_declination; }
    QComboBox *baudBox() const { return m_baud; }
    QComboBox *rateBox() const { return m_rate; }
    QComboBox *contentBox() const { return m_content; }
    QSpinBox *addressBox() const { return m_address; }
    QPushButton *readDeclinationButton() const { return m_readDeclination; }
    QPushButton *setDeclinationButton() const { return m_setDeclination; }
    QPushButton *setBaudButton() const { return m_setBaud; }
    QPushButton *setRateButton() const { return m_setRate; }
    QPushButton *setContentButton() const { return m_setContent; }
    QPushButton *setAddressButton() const { return m_setAddress; }
    QPushButton *saveButton() const { return m_save; }
    QPushButton *resetButton() const { return m_reset; }
    QComboBox *angleBox() const { return m_angle; }
    QPushButton *readAngleButton() const { return m_readAngle; }
    QPushButton *readAddressButton() const { return m_readAddress; }

Q_SIGNALS:
    // A request finished (the same as the session's, for this panel's requests only).
    void requestFinished(const imudesk::device::Hec495Result &result);

protected:
    void changeEvent(QEvent *event) override;

private:
    void track(quint64 id);
    void onFinished(quint64 id, const device::Hec495Result &r);
    void setBusy(bool busy);
    void retranslate();
    void factoryReset();

    device::Hec495Session *m_session;
    quint64 m_pending = 0;
    bool m_confirmReset = true;
    QDoubleSpinBox *m_declination;
    QComboBox *m_baud, *m_rate, *m_content, *m_angle;
    QSpinBox *m_address;
    QPushButton *m_readDeclination, *m_setDeclination, *m_setBaud, *m_setRate, *m_setContent, *m_setAddress;
    QPushButton *m_save, *m_reset, *m_readAngle, *m_readAddress;
    QLabel *m_status, *m_note;
    QLabel *m_declinationLabel, *m_baudLabel, *m_rateLabel, *m_contentLabel, *m_addressLabel, *m_angleLabel;
};

} // namespace imudesk::ui
