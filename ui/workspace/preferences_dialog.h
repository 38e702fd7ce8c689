#pragma once
// Edit > Preferences: language, units, display frame, chart refresh and history,
// recording folder and file pattern, auto-reconnect. Works on a Preferences value; the
// main window stores and applies what the dialog returns.
#include "workspace/preferences.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace imudesk::ui {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(const Preferences &prefs, QWidget *parent = nullptr);

    Preferences preferences() const;
    void setPreferences(const Preferences &prefs);

    QComboBox *languageCombo() const { return m_language; }
    QComboBox *accelCombo() const { return m_accel; }
    QComboBox *rateCombo() const { return m_rate; }
    QComboBox *frameCombo() const { return m_frame; }
    QSpinBox *refreshSpin() const { return m_refresh; }
    QSpinBox *historySpin() const { return m_history; }
    QLineEdit *folderEdit() const { return m_folder; }
    QLineEdit *patternEdit() const { return m_pattern; }
    QCheckBox *reconnectCheck() const { return m_reconnect; }
    QLabel *patternExample() const { return m_patternExample; }

private:
    void browseFolder();
    void updatePatternExample();

    QComboBox *m_language = nullptr;
    QLabel *m_restartNote = nullptr;
    QComboBox *m_accel = nullptr;
    QComboBox *m_rate = nullptr;
    QComboBox *m_frame = nullptr;
    QSpinBox *m_refresh = nullptr;
    QSpinBox *m_history = nullptr;
    QLineEdit *m_folder = nullptr;
    QLineEdit *m_pattern = nullptr;
    QLabel *m_patternExample = nullptr;
    QCheckBox *m_reconnect = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
    QString m_initialLanguage;
};

} // namespace imudesk::ui
