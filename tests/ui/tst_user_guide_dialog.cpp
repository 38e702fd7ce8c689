// Help ▸ User guide (ui/workspace/help_dialogs.h, issue 53 point 15): the guide's pictures
// load (docs/screenshots/*.png, built in beside the guide), none wider than the dialog's
// column; a table of contents from its headings, a click on one shows that section at the top;
// in Chinese the dialog's words are Chinese and a line says that the guide itself is in English.
#include "../common/test_main.h"
#include "workspace/help_dialogs.h"
#include "workspace/language_switcher.h"

#include <QImage>
#include <QLabel>
#include <QScrollBar>
#include <QTest>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QTextFragment>
#include <QTreeWidget>

using namespace imudesk;

namespace {

struct Picture {
    QString name;
    QImage image;
    double width = 0;
};

std::vector<Picture> pictures(QTextDocument *doc)
{
    std::vector<Picture> out;
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextFragment f = it.fragment();
            if (!f.isValid() || !f.charFormat().isImageFormat())
                continue;
            const QTextImageFormat format = f.charFormat().toImageFormat();
            const QVariant res = doc->resource(QTextDocument::ImageResource, QUrl(format.name()));
            QImage image = res.typeId() == QMetaType::QByteArray ? QImage::fromData(res.toByteArray())
                         : res.typeId() == QMetaType::QPixmap    ? res.value<QPixmap>().toImage()
                                                                  : res.value<QImage>();
            out.push_back({format.name(), image, format.width()});
        }
    return out;
}

QTreeWidgetItem *findEntry(QTreeWidget *tree, const QString &text)
{
    for (QTreeWidgetItemIterator it(tree); *it; ++it)
        if ((*it)->text(0) == text)
            return *it;
    return nullptr;
}

} // namespace

class TstUserGuideDialog : public QObject {
    Q_OBJECT
    ui::LanguageSwitcher m_language;

private Q_SLOTS:
    void cleanup()
    {
        QString error;
        QVERIFY2(m_language.setLanguage(QStringLiteral("en"), QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
    }

    void picturesLoad()
    {
        ui::UserGuideDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        const auto shown = pictures(dialog.browser()->document());
        // The guide names about twenty screenshots; every one is there and is a picture.
        QVERIFY2(shown.size() >= 15, qPrintable(QString::number(shown.size())));
        // Each within the guide's width, whatever the dialog's (a picture is 1366 px or wider).
        for (const QSize &size : {QSize(700, 500), QSize(1100, 800)}) {
            dialog.resize(size);
            QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
            QCoreApplication::processEvents();
            const int room = dialog.browser()->viewport()->width();
            for (const Picture &p : pictures(dialog.browser()->document())) {
                QVERIFY2(!p.image.isNull(), qPrintable(p.name + QStringLiteral(" did not load")));
                QVERIFY2(p.width > 0 && p.width <= room,
                         qPrintable(QStringLiteral("%1: %2 px in %3").arg(p.name).arg(p.width).arg(room)));
            }
        }
    }

    void contentsFromTheHeadings()
    {
        ui::UserGuideDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        auto *contents = dialog.findChild<QTreeWidget *>(QStringLiteral("userGuideContents"));
        QVERIFY2(contents, "no table of contents");
        QVERIFY(contents->isVisible());
        int headings = 0;
        for (QTextBlock b = dialog.browser()->document()->begin(); b.isValid(); b = b.next())
            headings += b.blockFormat().headingLevel() >= 1 && b.blockFormat().headingLevel() <= 3 ? 1 : 0;
        int entries = 0;
        for (QTreeWidgetItemIterator it(contents); *it; ++it)
            ++entries;
        QVERIFY(headings > 10);
        QCOMPARE(entries, headings);
        // A click on a section near the end shows it at the top of the view.
        QTreeWidgetItem *entry = findEntry(contents, QStringLiteral("The results database"));
        QVERIFY(entry);
        contents->scrollToItem(entry);
        const QRect r = contents->visualItemRect(entry);
        QTest::mouseClick(contents->viewport(), Qt::LeftButton, {}, r.center());
        QTextBrowser *browser = dialog.browser();
        QVERIFY(browser->verticalScrollBar()->value() > 0);
        const QRect at = browser->cursorRect();
        QVERIFY2(at.top() >= 0 && at.top() < browser->viewport()->height() / 4,
                 qPrintable(QStringLiteral("the heading at %1 of %2").arg(at.top()).arg(browser->viewport()->height())));
        QCOMPARE(browser->textCursor().block().text().trimmed(), QStringLiteral("The results database"));
    }

    void chineseSaysTheGuideIsEnglish()
    {
        ui::UserGuideDialog english;
        auto *noteEn = english.findChild<QLabel *>(QStringLiteral("userGuideLanguageNote"));
        QVERIFY2(noteEn, "no language note");
        QVERIFY(noteEn->isHidden()); // English: nothing to say
        QString error;
        QVERIFY2(m_language.setLanguage(QStringLiteral("zh_CN"), QString::fromUtf8(IMUDESK_QM_DIR), &error), qPrintable(error));
        ui::UserGuideDialog dialog;
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        const auto chinese = [](const QString &s) {
            return std::any_of(s.begin(), s.end(), [](QChar c) { return c.unicode() >= 0x4E00 && c.unicode() <= 0x9FFF; });
        };
        QVERIFY2(chinese(dialog.windowTitle()), qPrintable(dialog.windowTitle()));
        auto *note = dialog.findChild<QLabel *>(QStringLiteral("userGuideLanguageNote"));
        QVERIFY(note && note->isVisible());
        QVERIFY2(chinese(note->text()), qPrintable(note->text()));
        auto *contents = dialog.findChild<QTreeWidget *>(QStringLiteral("userGuideContents"));
        QVERIFY(contents);
        QVERIFY2(chinese(contents->headerItem()->text(0)), qPrintable(contents->headerItem()->text(0)));
    }
};

IMUDESK_TEST_MAIN(TstUserGuideDialog)
#include "tst_user_guide_dialog.moc"
