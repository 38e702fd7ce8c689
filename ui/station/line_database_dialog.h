#pragma once
// The station's line database (issue 38): the dialog behind the station window's "Line
// database…" button, and the words the station's summary line gives the upload.
//
// LineDatabaseDialog: the line's PostgreSQL server as a URL (a password typed into it is kept in
// the station's settings as typed, so ~/.pgpass is the better place for it), the shared folder
// the reports and recordings are copied to, and Test connection, which opens the database from
// a thread of its own (the dialog keeps answering while a server does not) as the station's
// uploader will, creating the schema on a fresh server, and says "Connected: schema N" or why
// not. OK hands the two back to the station window, which stores them.
//
// LineDatabaseStatus follows the uploader of the station's current run (ResultsUploader::
// stateChanged) and words it for the summary line: results waiting, all uploaded, or failing.
#include <QDialog>
#include <QPointer>

QT_BEGIN_NAMESPACE
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QPushButton;
QT_END_NAMESPACE

namespace imudesk::results {
class ResultsQuery;
class ResultsUploader;
}

namespace imudesk::ui {

using results::ResultsQuery;

class LineDatabaseDialog : public QDialog {
    Q_OBJECT

public:
    LineDatabaseDialog(const QString &url, const QString &artifactFolder, QWidget *parent = nullptr);

    QString url() const;
    QString artifactFolder() const;
    // Opens the database in the background; the result line says how it went.
    void testConnection();
    bool testing() const;
    QString testResult() const;

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateState();
    void chooseFolder();

    ResultsQuery *m_query = nullptr;
    bool m_testing = false;
    QLabel *m_about = nullptr;
    QLabel *m_urlTitle = nullptr;
    QLineEdit *m_url = nullptr;
    QLabel *m_urlNote = nullptr;
    QLabel *m_folderTitle = nullptr;
    QLineEdit *m_folder = nullptr;
    QPushButton *m_browse = nullptr;
    QPushButton *m_test = nullptr;
    QLabel *m_result = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};

class LineDatabaseStatus : public QObject {
    Q_OBJECT

public:
    explicit LineDatabaseStatus(QObject *parent = nullptr);

    // The uploader of the station's current run; nullptr: none (no line database).
    void follow(results::ResultsUploader *uploader);
    // What the summary line appends (" · 3 results waiting to upload"); empty without an uploader.
    QString text() const;
    // What its tooltip adds (where the results go, or the whole error).
    QString toolTip() const;

Q_SIGNALS:
    void changed();

private:
    QPointer<results::ResultsUploader> m_uploader;
    bool m_seen = false; // a pass has reported
    int m_pending = 0;
    bool m_connected = false;
    QString m_error;
};

} // namespace imudesk::ui
