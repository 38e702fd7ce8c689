#include "workspace/help_dialogs.h"

#include <QAbstractTextDocumentLayout>
#include <QAction>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFile>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QPixmap>
#include <QRegularExpression>
#include <QScreen>
#include <QScrollBar>
#include <QSplitter>
#include <QTableWidget>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QTextTable>
#include <QTextFragment>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <vector>

namespace imudesk::ui {

namespace {

// A dialog's size on its screen: `share` of the available area, at most `most`.
void sizeOnScreen(QDialog *dialog, double share, QSize most)
{
    QSize size = most;
    if (const QScreen *screen = dialog->screen())
        size = size.boundedTo((screen->availableGeometry().size() * share));
    dialog->resize(size);
}

QString plainText(const QAction *action)
{
    QString text = action->text();
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    text.replace(QLatin1String("&&"), QLatin1String("&"));
    if (text.endsWith(QChar(0x2026)))
        text.chop(1);
    return text;
}

} // namespace

namespace {
// The note's English text: shown only when the language of the moment translates it.
const char *const kGuideLanguageNote = QT_TRANSLATE_NOOP(
    "imudesk::ui::UserGuideDialog", "The user guide is written in English; it is not available in your language yet. "
                                    "The menus and dialogs it describes are shown in your language.");
constexpr int kBlockRole = Qt::UserRole + 1; // a heading's block in the guide
} // namespace

QString UserGuideDialog::guideMarkdown()
{
    QFile file(QStringLiteral(":/docs/USER_GUIDE.md"));
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    return QString::fromUtf8(file.readAll());
}

UserGuideDialog::UserGuideDialog(QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("userGuideDialog"));
    m_note = new QLabel(this);
    m_note->setObjectName(QStringLiteral("userGuideLanguageNote"));
    m_note->setWordWrap(true);
    m_contents = new QTreeWidget(this);
    m_contents->setObjectName(QStringLiteral("userGuideContents"));
    m_contents->setColumnCount(1);
    m_contents->setUniformRowHeights(true);
    m_contents->setTextElideMode(Qt::ElideRight);
    m_browser = new QTextBrowser(this);
    m_browser->setObjectName(QStringLiteral("userGuideBrowser"));
    m_browser->setOpenExternalLinks(true);
    // The pictures' relative paths (screenshots/x.png) are found beside the guide in the resources.
    m_browser->setSearchPaths({QStringLiteral(":/docs")});
    m_browser->document()->setBaseUrl(QUrl(QStringLiteral("qrc:/docs/")));
    const QString guide = guideMarkdown();
    if (guide.isEmpty()) {
        m_browser->setPlainText(tr("The user guide is not part of this build. It is docs/USER_GUIDE.md in "
                                   "ImuDesk's source."));
    } else {
        m_browser->setMarkdown(guide);
        fitPictures();
        m_browser->viewport()->installEventFilter(this);
    }
    fillContents();
    connect(m_contents, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem *item) { showSection(item); });
    connect(m_contents, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem *item) { showSection(item); });
    auto *split = new QSplitter(Qt::Horizontal, this);
    split->setChildrenCollapsible(false);
    split->addWidget(m_contents);
    split->addWidget(m_browser);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 3);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_note);
    layout->addWidget(split, 1);
    layout->addWidget(buttons);
    retranslateUi();
    sizeOnScreen(this, 0.85, QSize(1280, 1000));
    split->setSizes({width() / 4, width() * 3 / 4});
}

void UserGuideDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange && m_note)
        retranslateUi();
    QDialog::changeEvent(event);
}

void UserGuideDialog::retranslateUi()
{
    setWindowTitle(tr("ImuDesk user guide"));
    m_contents->setHeaderLabels({tr("Contents")});
    const QString note = tr(kGuideLanguageNote);
    m_note->setText(note);
    m_note->setVisible(note != QLatin1String(kGuideLanguageNote));
}

void UserGuideDialog::fillContents()
{
    // One entry per heading (#, ##, ###), nested by level, in the guide's order.
    m_contents->clear();
    QTreeWidgetItem *parents[4] = {};
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next()) {
        const int level = b.blockFormat().headingLevel();
        if (level < 1 || level > 3 || b.text().trimmed().isEmpty())
            continue;
        QTreeWidgetItem *parent = nullptr;
        for (int l = level - 1; l >= 1 && !parent; --l)
            parent = parents[l];
        auto *item = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(m_contents);
        item->setText(0, b.text().trimmed());
        item->setToolTip(0, b.text().trimmed());
        item->setData(0, kBlockRole, b.blockNumber());
        parents[level] = item;
        for (int l = level + 1; l <= 3; ++l)
            parents[l] = nullptr;
    }
    m_contents->expandToDepth(1);
}

void UserGuideDialog::showSection(const QTreeWidgetItem *item)
{
    if (!item)
        return;
    const QTextBlock block = m_browser->document()->findBlockByNumber(item->data(0, kBlockRole).toInt());
    if (!block.isValid())
        return;
    QTextCursor cursor(block);
    m_browser->setTextCursor(cursor);
    // The heading at the top of the view, not just somewhere in it.
    const QRectF r = m_browser->document()->documentLayout()->blockBoundingRect(block);
    m_browser->verticalScrollBar()->setValue(int(r.top()));
}

bool UserGuideDialog::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_browser->viewport() && event->type() == QEvent::Resize)
        fitPictures();
    return QDialog::eventFilter(watched, event);
}

void UserGuideDialog::fitPictures()
{
    // The screenshots are 1366 or 1920 px wide: each at most the guide's width (a table's two
    // side by side half of it), so the guide reads without scrolling sideways; the picture is
    // whole, only smaller. Its own width is kept in the format (kNaturalWidth) for the next fit.
    constexpr int kNaturalWidth = QTextFormat::UserProperty + 1;
    constexpr int kNaturalHeight = QTextFormat::UserProperty + 2;
    QTextDocument *doc = m_browser->document();
    const int column = std::max(240, m_browser->viewport()->width() - 2 * int(doc->documentMargin()) - 24);
    struct Picture {
        int position, length;
        QTextImageFormat format;
    };
    std::vector<Picture> pictures;
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
        const bool inTable = QTextCursor(b).currentTable() != nullptr;
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextFragment f = it.fragment();
            if (!f.isValid() || !f.charFormat().isImageFormat())
                continue;
            QTextImageFormat image = f.charFormat().toImageFormat();
            int natural = image.intProperty(kNaturalWidth), naturalHeight = image.intProperty(kNaturalHeight);
            if (natural <= 0) {
                const QVariant res = doc->resource(QTextDocument::ImageResource, QUrl(image.name()));
                QImage picture;
                if (res.typeId() == QMetaType::QImage)
                    picture = res.value<QImage>();
                else if (res.typeId() == QMetaType::QPixmap)
                    picture = res.value<QPixmap>().toImage();
                else if (res.typeId() == QMetaType::QByteArray)
                    picture = QImage::fromData(res.toByteArray());
                if (picture.isNull())
                    continue;
                natural = picture.width();
                naturalHeight = picture.height();
                image.setProperty(kNaturalWidth, natural);
                image.setProperty(kNaturalHeight, naturalHeight);
            }
            const int width = std::min(natural, inTable ? (column - 24) / 2 : column);
            if (qFuzzyCompare(image.width(), double(width)))
                continue;
            image.setWidth(width);
            image.setHeight(double(width) * naturalHeight / natural);
            pictures.push_back({f.position(), f.length(), image});
        }
    }
    for (const Picture &p : pictures) {
        QTextCursor c(doc);
        c.setPosition(p.position);
        c.setPosition(p.position + p.length, QTextCursor::KeepAnchor);
        c.setCharFormat(p.format);
    }
}

ShortcutsDialog::ShortcutsDialog(const QList<QAction *> &actions, QWidget *parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    setWindowTitle(tr("Keyboard shortcuts"));
    QList<QPair<QString, QString>> rows;
    for (const QAction *action : actions) {
        const QList<QKeySequence> keys = action->shortcuts();
        if (keys.isEmpty() || action->text().isEmpty())
            continue;
        QStringList texts;
        for (const QKeySequence &k : keys)
            texts << k.toString(QKeySequence::NativeText);
        const QPair<QString, QString> row{plainText(action), texts.join(tr(" or "))};
        if (!rows.contains(row))
            rows << row;
    }
    std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) {
        return a.first.localeAwareCompare(b.first) < 0;
    });
    m_table = new QTableWidget(int(rows.size()), 2, this);
    m_table->setObjectName(QStringLiteral("shortcutsTable"));
    m_table->setHorizontalHeaderLabels({tr("Action"), tr("Keys")});
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setWordWrap(false);
    for (int r = 0; r < rows.size(); ++r) {
        m_table->setItem(r, 0, new QTableWidgetItem(rows[r].first));
        m_table->setItem(r, 1, new QTableWidgetItem(rows[r].second));
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setStretchLastSection(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    const int width = m_table->columnWidth(0) + m_table->columnWidth(1) + 60;
    const int height = m_table->verticalHeader()->length() + m_table->horizontalHeader()->height() + 90;
    sizeOnScreen(this, 0.85, QSize(std::max(width, 420), height));
}

} // namespace imudesk::ui
