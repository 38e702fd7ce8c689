#pragma once
// The serial firmware update dialog: choose a file (start address, size, CRC-32; a .bin
// asks for its start address), the module's current versions, progress with bytes/s and
// time left, cancel, a log, and the new version at the end. The update itself runs in
// core (firmware::FirmwareUpdater, its own thread); the dialog never touches the port.
// The port must be free: close the device's session before opening the dialog.
#include "firmware/update_flow.h"
#include "model/device_identity.h"

#include <QDialog>

#include <optional>

QT_BEGIN_NAMESPACE
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
QT_END_NAMESPACE

namespace imudesk::firmware {
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

    // Loads and checks a firmware file (also what "Choose..." does); false shows why.
    bool loadFile(const QString &path);
    // Starts the update with the loaded image; false if none or one is running.
    bool startUpdate();
    void cancelUpdate();
    bool isRunning() const;
    // After a finished update: the result (ok, message, versions).
    const firmware::UpdateFlow::Result &result() const;

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

    QString m_port;
    int m_baud;
    std::optional<protocol::ihex::FirmwareImage> m_image;
    firmware::FirmwareUpdater *m_updater = nullptr;

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
    QPushButton *m_start = nullptr;
    QPushButton *m_cancel = nullptr;
};

} // namespace imudesk::ui
