#pragma once
// Device > Connect over Modbus RTU… / Connect over CAN…: the link's parameters, with the
// simulated devices offered so that both work without hardware. The dialog only collects
// choices; the main window opens the link (device::LinkOpener, ui/families) with them.
//
// Folder ui/bus/: Modbus RTU and CAN. These connect dialogs, the ModbusScanDialog, the
// RegisterBrowser, the CanConfigPanel and the CanMonitorWidget. It mirrors the bus sessions of
// core/device (ModbusSession, CanSession and their option types) and the codecs of
// core/protocol/modbus and core/protocol/can. The register browser shows
// models::RegisterTableModel and the CAN monitor models::CanFrameMonitorModel, each in a
// QTableView.
#include "device/can_session_types.h"
#include "device/modbus_types.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QLabel;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLineEdit;
class QSpinBox;

namespace imudesk::ui {

class ModbusConnectDialog : public QDialog {
    Q_OBJECT
public:
    explicit ModbusConnectDialog(QWidget *parent = nullptr);

    device::ModbusOptions options() const;
    // True when the choice is one of the simulated devices (options().port is then empty).
    bool simulate() const;

    QComboBox *portCombo() const { return m_port; }
    QComboBox *kindCombo() const { return m_kind; }
    QSpinBox *nodeSpin() const { return m_node; }
    QComboBox *baudCombo() const { return m_baud; }

private:
    void updateDefaults();

    QComboBox *m_port = nullptr;
    QComboBox *m_kind = nullptr;
    QSpinBox *m_node = nullptr;
    QComboBox *m_baud = nullptr;
    QComboBox *m_parity = nullptr;
    QDoubleSpinBox *m_poll = nullptr;
    QCheckBox *m_ship = nullptr;
};

class CanConnectDialog : public QDialog {
    Q_OBJECT
public:
    explicit CanConnectDialog(QWidget *parent = nullptr);

    device::CanSessionOptions options() const;
    bool simulate() const;

    QComboBox *pluginCombo() const { return m_plugin; }
    QComboBox *interfaceCombo() const { return m_interface; }
    QComboBox *protocolCombo() const { return m_protocol; }
    QCheckBox *simulateCheck() const { return m_simulate; }
    QCheckBox *hec495ExtendedCheck() const { return m_hecExtended; }
    QComboBox *bitrateCombo() const { return m_bitrate; }
    QLabel *rateHint() const { return m_rateHint; }
    QCheckBox *fdCheck() const { return m_fd; }
    QComboBox *dataBitrateCombo() const { return m_dataBitrate; }

private:
    void refreshInterfaces();
    // The bit rates the chosen protocol's manual lists, its factory rate preselected.
    void refreshRates();

    QComboBox *m_plugin = nullptr;
    QComboBox *m_interface = nullptr;
    QComboBox *m_bitrate = nullptr;
    QComboBox *m_protocol = nullptr;
    QSpinBox *m_node = nullptr;
    QComboBox *m_firmware = nullptr;
    QCheckBox *m_simulate = nullptr;
    QCheckBox *m_hecExtended = nullptr; // HEC495: the extended-frame variant
    QLabel *m_rateHint = nullptr;
    QCheckBox *m_fd = nullptr;
    QComboBox *m_dataBitrate = nullptr;
    int m_protocolShown = -1;
};

} // namespace imudesk::ui
