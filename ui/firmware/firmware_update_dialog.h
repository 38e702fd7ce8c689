#pragma once
// The firmware update dialog: choose a file (start address, size, CRC-32; a .bin asks for
// its start address), the link (the serial port given, KBOOT; or a CAN bus: plugin,
// interface, bit rate, node, CANopen SDO 0x1F51), the module's current versions, progress
// with bytes/s and time left, cancel, a log, and the new version at the end. The update
// itself runs in core (firmware::FirmwareUpdater / CanFirmwareUpdater, their own threads);
// the dialog never touches the port or the bus. The serial port must be free: close the
// device's session before opening the dialog.
//
// Folder ui/firmware/: this firmware update dialog only. It mirrors core/firmware: the update
// runs in its state machines (UpdateFlow: KBOOT over the serial port; CanUpdateFlow: CANopen
// SDO over a CAN bus), each on the worker thread of a FirmwareUpdater or CanFirmwareUpdater;
// the dialog shows their progress and log. No item models.
#include "core/firmware/can_update_flow.h"
#include "core/firmware/update_flow.h"
#include "model/device_identity.h"

#include <QDialog>

#include <optional>

QT_BEGIN_NAMESPACE
class QComboBox;
class QGroupBox;
class QSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
QT_END_NAMESPACE

namespace imudesk::firmware {
class CanFirmwareUpdater;
class FirmwareUpdater;
}

namespace imudesk::ui {

class FirmwareUpdateDialog : public QDialog {
    Q_OBJECT

public:
    // identity: what the session knew about the module (versions shown before the update).
    FirmwareUpdateDialog(const QString &portName, int baud, const std::optional<model::DeviceIdentity> &identity,
                         QWidget *parent = nullptr);
    ~FirmwareUpdateDialog() override;

    enum class Link { Serial, Can };
    // The link the next update uses (the "Link" choice); Serial by default.
    void setLink(Link link);
    Link link() const;
    // Presets the CAN fields (plugin as QCanBus names it, interface, bit/s with 0 = leave the
    // interface's setting, CANopen node 1..127).
    void setCanBus(const QString &plugin, const QString &interfaceName, int bitrate, int node);

    // For a simulated module (the demo): a "Demo image" button that writes an application image
    // of a newer version, which the simulated bootloader accepts, and loads it.
    void setDemoImageOffered(bool offered);
    // Writes and loads that image; false shows why (e.g. no room in the temporary folder).
    bool loadDemoImage();
    // Loads and checks a firmware file (also what "Choose..." does); false shows why.
    bool loadFile(const QString &path);
    // Starts the update with the loaded image; false if none or one is running. While the port
    // is not free yet (setPortFree), the update starts as soon as it is.
    bool startUpdate();
    // The serial port is free for the update (the tab that lent it has closed its link); true
    // unless told otherwise.
    void setPortFree(bool free);
    void cancelUpdate();
    bool isRunning() const;
    // After a finished serial update: the result (ok, message, versions).
    const firmware::UpdateFlow::Result &result() const;
    // After a finished CAN update: the result (ok, message, verification, versions).
    const firmware::CanUpdateFlow::Result &canResult() const;

Q_SIGNALS:
    void updateFinished(bool ok);

protected:
    void reject() override;

private:
    void chooseFile();
    void onState(int state, const QString &name);
    void onProgress(qulonglong done, qulonglong total, double bytesPerSecond, double secondsLeft);
    void onLog(const QString &line);
    void onFinished(bool ok, const QString &message);
    void updateButtons();
    void onLinkChanged();
    QWidget *buildCanBox();

    QString m_port;
    int m_baud;
    std::optional<protocol::ihex::FirmwareImage> m_image;
    firmware::FirmwareUpdater *m_updater = nullptr;
    firmware::CanFirmwareUpdater *m_canUpdater = nullptr;
    bool m_lastWasCan = false;
    bool m_portFree = true;
    bool m_startWhenFree = false;

    QComboBox *m_link = nullptr;
    QGroupBox *m_canBox = nullptr;
    QComboBox *m_canPlugin = nullptr;
    QLineEdit *m_canInterface = nullptr;
    QSpinBox *m_canBitrate = nullptr;
    QSpinBox *m_canNode = nullptr;

    QLineEdit *m_file = nullptr;
    QLineEdit *m_binStart = nullptr;
    QLabel *m_imageInfo = nullptr;
    QLabel *m_versions = nullptr;
    QLabel *m_state = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_rate = nullptr;
    QPlainTextEdit *m_log = nullptr;
    QLabel *m_outcome = nullptr;
    QPushButton *m_choose = nullptr;
    QPushButton *m_demoImage = nullptr;
    QString m_demoImagePath;
    QPushButton *m_start = nullptr;
    QPushButton *m_cancel = nullptr;
};

} // namespace imudesk::ui
