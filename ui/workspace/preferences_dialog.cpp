#include "workspace/preferences_dialog.h"

#include "recording/recording_controls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace imudesk::ui {

PreferencesDialog::PreferencesDialog(const Preferences &prefs, QWidget *parent) : QDialog(parent)
{
    setWindowTitle(tr("Preferences"));
    setObjectName(QStringLiteral("preferencesDialog"));

    auto *general = new QGroupBox(tr("Language"), this);
    auto *generalForm = new QFormLayout(general);
    m_language = new QComboBox(general);
    m_language->addItem(tr("System language"), QString());
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("简体中文"), QStringLiteral("zh_CN"));
    m_language->addItem(QStringLiteral("繁體中文"), QStringLiteral("zh_TW"));
    m_language->setToolTip(tr("The language of the user interface. Takes effect the next time ImuDesk starts."));
    generalForm->addRow(tr("&Language:"), m_language);
    m_restartNote = new QLabel(tr("The new language is used after a restart."), general);
    m_restartNote->setWordWrap(true);
    m_restartNote->hide();
    generalForm->addRow(m_restartNote);

    auto *display = new QGroupBox(tr("Display"), this);
    auto *displayForm = new QFormLayout(display);
    m_accel = new QComboBox(display);
    m_accel->addItem(tr("G (1 G = 9.8 m/s²)"), int(model::AccelUnit::G));
    m_accel->addItem(tr("m/s²"), int(model::AccelUnit::MetresPerSecondSquared));
    m_accel->setToolTip(tr("Unit of the accelerometer values and chart. Recorded data keeps the device's unit (G)."));
    displayForm->addRow(tr("&Acceleration:"), m_accel);
    m_rate = new QComboBox(display);
    m_rate->addItem(tr("deg/s"), int(model::RateUnit::DegreesPerSecond));
    m_rate->addItem(tr("rad/s"), int(model::RateUnit::RadiansPerSecond));
    m_rate->setToolTip(tr("Unit of the gyroscope values and chart. Recorded data keeps the device's unit (deg/s)."));
    displayForm->addRow(tr("Angular &rate:"), m_rate);
    m_frame = new QComboBox(display);
    m_frame->addItem(tr("ENU (east, north, up)"), int(Preferences::Frame::Enu));
    m_frame->addItem(tr("NED (north, east, down)"), int(Preferences::Frame::Ned));
    m_frame->setToolTip(tr("World frame of the 3D attitude view."));
    displayForm->addRow(tr("Attitude &frame:"), m_frame);
    m_refresh = new QSpinBox(display);
    m_refresh->setRange(Preferences::kMinRefreshHz, Preferences::kMaxRefreshHz);
    m_refresh->setSuffix(tr(" Hz"));
    m_refresh->setToolTip(tr("How often charts and values are redrawn (%1 to %2 Hz). Lower rates use less CPU.")
                              .arg(Preferences::kMinRefreshHz)
                              .arg(Preferences::kMaxRefreshHz));
    displayForm->addRow(tr("Chart &refresh:"), m_refresh);
    m_history = new QSpinBox(display);
    m_history->setRange(Preferences::kMinHistoryMinutes, Preferences::kMaxHistoryMinutes);
    m_history->setSuffix(tr(" min"));
    m_history->setToolTip(tr("The longest time window a chart can show (%1 to %2 minutes).")
                              .arg(Preferences::kMinHistoryMinutes)
                              .arg(Preferences::kMaxHistoryMinutes));
    displayForm->addRow(tr("Chart &history:"), m_history);

    auto *recording = new QGroupBox(tr("Recording"), this);
    auto *recordingForm = new QFormLayout(recording);
    auto *folderRow = new QHBoxLayout;
    m_folder = new QLineEdit(recording);
    m_folder->setPlaceholderText(tr("Documents folder"));
    m_folder->setToolTip(tr("Where new recordings are written."));
    auto *browse = new QPushButton(tr("&Browse…"), recording);
    connect(browse, &QPushButton::clicked, this, &PreferencesDialog::browseFolder);
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(browse);
    recordingForm->addRow(tr("&Folder:"), folderRow);
    m_pattern = new QLineEdit(recording);
    m_pattern->setToolTip(tr("File name of a new recording. {product}, {serial}, {date} and {time} are replaced."));
    recordingForm->addRow(tr("File &pattern:"), m_pattern);
    m_patternExample = new QLabel(recording);
    m_patternExample->setTextInteractionFlags(Qt::TextSelectableByMouse);
    recordingForm->addRow(tr("Example:"), m_patternExample);
    connect(m_pattern, &QLineEdit::textChanged, this, &PreferencesDialog::updatePatternExample);

    auto *connection = new QGroupBox(tr("Connection"), this);
    auto *connectionLayout = new QVBoxLayout(connection);
    m_reconnect = new QCheckBox(tr("&Reconnect by itself when an unplugged device comes back"), connection);
    m_reconnect->setToolTip(tr("After a cable is pulled, wait for the same device (USB serial number, else port) and "
                               "reconnect at the last baud rate."));
    connectionLayout->addWidget(m_reconnect);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(general);
    layout->addWidget(display);
    layout->addWidget(recording);
    layout->addWidget(connection);
    layout->addStretch(1);
    layout->addWidget(m_buttons);

    setPreferences(prefs);
    m_initialLanguage = prefs.language;
    connect(m_language, &QComboBox::currentIndexChanged, this, [this] {
        m_restartNote->setVisible(m_language->currentData().toString() != m_initialLanguage);
    });
}

void PreferencesDialog::setPreferences(const Preferences &prefs)
{
    const auto select = [](QComboBox *combo, const QVariant &value) {
        const int i = combo->findData(value);
        combo->setCurrentIndex(i >= 0 ? i : 0);
    };
    select(m_language, prefs.language);
    select(m_accel, int(prefs.units.accel));
    select(m_rate, int(prefs.units.rate));
    select(m_frame, int(prefs.frame));
    m_refresh->setValue(prefs.refreshHz);
    m_history->setValue(prefs.historyMinutes);
    m_folder->setText(prefs.recordingFolder);
    m_pattern->setText(prefs.recordingPattern);
    m_reconnect->setChecked(prefs.autoReconnect);
    updatePatternExample();
}

Preferences PreferencesDialog::preferences() const
{
    Preferences p;
    p.language = m_language->currentData().toString();
    p.units.accel = model::AccelUnit(m_accel->currentData().toInt());
    p.units.rate = model::RateUnit(m_rate->currentData().toInt());
    p.frame = Preferences::Frame(m_frame->currentData().toInt());
    p.refreshHz = m_refresh->value();
    p.historyMinutes = m_history->value();
    p.recordingFolder = m_folder->text().trimmed();
    if (!m_pattern->text().trimmed().isEmpty())
        p.recordingPattern = m_pattern->text().trimmed();
    p.autoReconnect = m_reconnect->isChecked();
    return p;
}

void PreferencesDialog::browseFolder()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Recording folder"), preferences().effectiveRecordingFolder());
    if (!dir.isEmpty())
        m_folder->setText(dir);
}

void PreferencesDialog::updatePatternExample()
{
    // The name the recording controls will give, for an example device.
    m_patternExample->setText(RecordingControls::expandPattern(preferences().recordingPattern, QStringLiteral("HI14R3"),
                                                               QStringLiteral("2181B60A"),
                                                               QDateTime::currentDateTime()));
}

} // namespace imudesk::ui
