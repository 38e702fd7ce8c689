#include "ui/station/line_database_dialog.h"

#include "core/results/results_store.h"
#include "core/results/results_uploader.h"
#include "core/results/results_query.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>

namespace imudesk::ui {

using results::ResultsStore;

// ---------------------------------------------------------------- the dialog

LineDatabaseDialog::LineDatabaseDialog(const QString &url, const QString &artifactFolder, QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("lineDatabaseDialog"));
    m_query = new ResultsQuery(this);
    m_about = new QLabel(this);
    m_about->setWordWrap(true);
    m_urlTitle = new QLabel(this);
    m_url = new QLineEdit(url, this);
    m_url->setObjectName(QStringLiteral("lineDatabaseUrl"));
    m_url->setClearButtonEnabled(true);
    m_urlTitle->setBuddy(m_url);
    m_urlNote = new QLabel(this);
    m_urlNote->setObjectName(QStringLiteral("lineDatabaseNote"));
    m_urlNote->setWordWrap(true);
    connect(m_url, &QLineEdit::textChanged, this, &LineDatabaseDialog::updateState);
    m_folderTitle = new QLabel(this);
    m_folder = new QLineEdit(QDir::toNativeSeparators(artifactFolder), this);
    m_folder->setObjectName(QStringLiteral("artifactFolder"));
    m_folderTitle->setBuddy(m_folder);
    m_browse = new QPushButton(this);
    m_browse->setObjectName(QStringLiteral("browseArtifactFolder"));
    connect(m_browse, &QPushButton::clicked, this, &LineDatabaseDialog::chooseFolder);
    auto *folderRow = new QHBoxLayout;
    folderRow->addWidget(m_folder, 1);
    folderRow->addWidget(m_browse);
    m_test = new QPushButton(this);
    m_test->setObjectName(QStringLiteral("testConnection"));
    connect(m_test, &QPushButton::clicked, this, &LineDatabaseDialog::testConnection);
    m_result = new QLabel(this);
    m_result->setObjectName(QStringLiteral("connectionResult"));
    m_result->setWordWrap(true);
    m_result->setTextFormat(Qt::PlainText); // a server's error may hold any text
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *testRow = new QHBoxLayout;
    testRow->addWidget(m_test, 0, Qt::AlignTop);
    testRow->addWidget(m_result, 1);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

    auto *form = new QFormLayout;
    form->addRow(m_urlTitle, m_url);
    form->addRow(QString(), m_urlNote);
    form->addRow(m_folderTitle, folderRow);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_about);
    layout->addLayout(form);
    layout->addLayout(testRow);
    layout->addStretch(1);
    layout->addWidget(m_buttons);
    retranslateUi();
    resize(std::max(sizeHint().width(), 640), sizeHint().height());
}

void LineDatabaseDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_buttons)
        retranslateUi();
    QDialog::changeEvent(event);
}

void LineDatabaseDialog::retranslateUi()
{
    setWindowTitle(tr("Line database"));
    m_about->setText(tr("Every module this station tests is stored in its own database first (results.sqlite in the "
                        "report folder); with a line database set, the station also sends each result there, and "
                        "keeps it until the server has it."));
    m_urlTitle->setText(tr("Server:"));
    m_url->setPlaceholderText(QStringLiteral("postgresql://station@server/imudesk"));
    m_url->setToolTip(tr("The line's PostgreSQL database: postgresql://user@host[:port]/database. Empty: none. A "
                         "password typed here (user:password@host) is stored with the station's settings as typed; "
                         "put it into ~/.pgpass instead, which PostgreSQL reads by itself."));
    m_folderTitle->setText(tr("Shared artifact folder:"));
    m_folder->setToolTip(tr("A folder every station and the office can reach (a network share): each module's PDF "
                            "report and recording are copied there, checked against their SHA-256, and the line "
                            "database records that copy. Empty: the files stay on this station."));
    m_browse->setText(tr("Browse…"));
    m_test->setText(tr("Test connection"));
    m_test->setToolTip(tr("Connect to the server now, as the station will (a fresh database gets ImuDesk's tables)"));
    updateState();
}

QString LineDatabaseDialog::url() const
{
    return m_url->text().trimmed();
}

QString LineDatabaseDialog::artifactFolder() const
{
    return QDir::fromNativeSeparators(m_folder->text().trimmed());
}

bool LineDatabaseDialog::testing() const
{
    return m_testing;
}

QString LineDatabaseDialog::testResult() const
{
    return m_result->text();
}

void LineDatabaseDialog::updateState()
{
    const QString u = url();
    const bool valid = u.isEmpty() || ResultsStore::isServerUrl(u);
    if (!valid)
        m_urlNote->setText(tr("A line database is a PostgreSQL server: its address starts with postgresql://"));
    else if (!QUrl(u).password().isEmpty())
        m_urlNote->setText(tr("The password is stored with the station's settings as typed; ~/.pgpass keeps it out "
                              "of them."));
    else
        m_urlNote->clear();
    m_urlNote->setVisible(!m_urlNote->text().isEmpty());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(valid);
    m_test->setEnabled(!m_testing && !u.isEmpty() && valid);
}

void LineDatabaseDialog::chooseFolder()
{
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Shared artifact folder"), artifactFolder());
    if (!dir.isEmpty())
        m_folder->setText(QDir::toNativeSeparators(dir));
}

void LineDatabaseDialog::testConnection()
{
    const QString location = url();
    if (location.isEmpty() || !ResultsStore::isServerUrl(location))
        return;
    m_testing = true;
    m_result->setStyleSheet(QString());
    m_result->setText(tr("Connecting to %1…").arg(ResultsStore::displayLocation(location)));
    updateState();
    struct Outcome {
        bool ok = false;
        int schema = 0;
        QString error;
    };
    // Opened with migrate: a fresh server gets its tables, as the station's first upload would
    // make them (with a role that may not create them, the error says so).
    m_query->ask(0,
                 [location](ResultsStore &store) {
                     Outcome o;
                     o.ok = store.open(location, &o.error, true);
                     o.schema = store.schemaVersion();
                     store.close();
                     return o;
                 },
                 [this](const Outcome &o) {
                     m_testing = false;
                     m_result->setStyleSheet(o.ok ? QStringLiteral("color: #2e7d32;") : QStringLiteral("color: #c62828;"));
                     m_result->setText(o.ok ? tr("Connected: schema %1").arg(o.schema) : o.error.trimmed());
                     updateState();
                 });
}

// ---------------------------------------------------------------- the summary line's words

LineDatabaseStatus::LineDatabaseStatus(QObject *parent) : QObject(parent) {}

void LineDatabaseStatus::follow(results::ResultsUploader *uploader)
{
    if (m_uploader)
        disconnect(m_uploader, nullptr, this, nullptr);
    m_uploader = uploader;
    m_seen = false;
    m_error.clear();
    if (uploader)
        connect(uploader, &results::ResultsUploader::stateChanged, this,
                [this](int pending, bool connected, const QString &error) {
                    m_seen = true;
                    m_pending = pending;
                    m_connected = connected;
                    m_error = error;
                    Q_EMIT changed();
                });
    Q_EMIT changed();
}

QString LineDatabaseStatus::text() const
{
    if (!m_uploader)
        return {};
    if (!m_seen)
        return tr(" · connecting to the line database…");
    if (!m_error.isEmpty())
        return tr(" · upload failing: %1").arg(m_error.simplified());
    if (m_pending > 0)
        return tr(" · %n result(s) waiting to upload", nullptr, m_pending);
    return tr(" · every result uploaded");
}

QString LineDatabaseStatus::toolTip() const
{
    if (!m_uploader)
        return {};
    const QString server = ResultsStore::displayLocation(m_uploader->options().server);
    if (m_seen && !m_error.isEmpty())
        return tr("Uploading to %1 fails: %2\nThe results wait in this station's database and go as soon as the "
                  "server answers; nothing is lost.")
            .arg(server, m_error.trimmed());
    return tr("Results go to the line database %1.").arg(server);
}

} // namespace imudesk::ui
