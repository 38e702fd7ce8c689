#pragma once
// Tools > Live bridge: the connected devices' samples, live, to Foxglove, Lichtblick and
// PlotJuggler. Where to listen (this computer only by default; another address shows that the
// protocol has no password), PlotJuggler's UDP target, start and stop, the clients, the
// messages sent and dropped, and the bridge's log. Not modal: it stays open beside the charts;
// the window's status bar shows the bridge while it runs. The choices are remembered.
#include <QDialog>

class QCheckBox;
class QComboBox;
class QGroupBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QSpinBox;

namespace imudesk::ui {

class BridgeController;

class LiveBridgeDialog : public QDialog {
    Q_OBJECT
public:
    explicit LiveBridgeDialog(BridgeController *controller, QWidget *parent = nullptr);

    // Starts with the choices shown (tests; the Start button); false with the reason shown.
    bool startBridge();
    void stopBridge();
    QString lastError() const { return m_lastError; }

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void updateState();
    void updateWarning();
    void loadSettings();
    void saveSettings() const;

    BridgeController *m_controller;
    QGroupBox *m_wsBox = nullptr;
    QLabel *m_addressLabel = nullptr;
    QComboBox *m_address = nullptr;
    QLabel *m_portLabel = nullptr;
    QSpinBox *m_port = nullptr;
    QLabel *m_warning = nullptr;
    QLabel *m_howTo = nullptr;
    QGroupBox *m_udpBox = nullptr;
    QLabel *m_udpHostLabel = nullptr;
    QLineEdit *m_udpHost = nullptr;
    QLabel *m_udpPortLabel = nullptr;
    QSpinBox *m_udpPort = nullptr;
    QPushButton *m_startStop = nullptr;
    QLabel *m_status = nullptr;
    QLabel *m_logLabel = nullptr;
    QPlainTextEdit *m_log = nullptr;
    QPushButton *m_close = nullptr;
    QString m_lastError;
};

} // namespace imudesk::ui
