#pragma once
// Record all devices as one session (issue 36 point 3): every connected tab that can record,
// into one folder (device::GroupRecording: each device's capture and session.json), with each
// device's bytes, frames and state while it runs, a device that drops out marked and the others
// going on. Afterwards the folder can be exported with the devices aligned on the common time
// (record::SessionExporter, in a worker thread) or aligned by twisting the fixture
// (TwistAlignDialog). Not modal: the tabs stay live behind it.
#include "record/group_recording.h"
#include "jobs/background_job.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>
#include <QWidget>

#include <functional>
#include <memory>

class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace imudesk::ui {

class SessionRecordingWindow : public QWidget {
    Q_OBJECT
public:
    struct Device {
        QPointer<device::Session> session;
        QString name;    // the tab's title
        QString address; // what it is connected to
        model::DeviceIdentity identity;
    };
    // Who provides the devices when Start is pressed (the connected tabs).
    using DeviceSource = std::function<std::vector<Device>()>;

    explicit SessionRecordingWindow(DeviceSource source, const QString &parentFolder, QWidget *parent = nullptr);
    ~SessionRecordingWindow() override;

    void setParentFolder(const QString &folder);
    QString parentFolder() const;
    bool isRecording() const { return m_group && m_group->running(); }
    // The folder of the last session recorded (empty before).
    QString lastSession() const { return m_lastSession; }
    const device::GroupRecording *group() const { return m_group.get(); }

public Q_SLOTS:
    void start();
    void stop();
    // The last session as one tidy CSV beside its folder, devices aligned (worker thread).
    void exportAligned();
    void openTwistAlign();

Q_SIGNALS:
    void recordingFinished(const QString &folder, bool ok);
    void exportFinished(bool ok, const QString &message);

protected:
    void changeEvent(QEvent *event) override;
    void closeEvent(QCloseEvent *event) override;

private:
    void retranslateUi();
    void refreshTable();
    void onFinished(const QString &manifestPath, const QString &error);
    void updateButtons();

    DeviceSource m_source;
    std::unique_ptr<device::GroupRecording> m_group;
    std::vector<Device> m_devices;
    QString m_lastSession;
    QLabel *m_intro = nullptr;
    QLabel *m_folderLabel = nullptr;
    QLineEdit *m_folderEdit = nullptr;
    QPushButton *m_chooseButton = nullptr;
    QPushButton *m_startButton = nullptr;
    QPushButton *m_stopButton = nullptr;
    QPushButton *m_exportButton = nullptr;
    QPushButton *m_alignButton = nullptr;
    QTableWidget *m_table = nullptr;
    QLabel *m_status = nullptr;
    QTimer m_refresh;
    QElapsedTimer m_elapsed;
    QString m_exportOutput;
    bool m_closeWhenDone = false; // closed while recording: close once the session is written
    jobs::BackgroundJob m_exportJob; // last: cancelled and joined before the rest goes
};

} // namespace imudesk::ui
