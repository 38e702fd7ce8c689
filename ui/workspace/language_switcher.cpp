#include "workspace/language_switcher.h"

#include <QCoreApplication>
#include <QFontDatabase>
#include <QApplication>
#include <QLibraryInfo>

namespace imudesk::ui {

LanguageSwitcher::LanguageSwitcher(QObject *parent) : QObject(parent) {}

LanguageSwitcher::~LanguageSwitcher()
{
    uninstall();
}

QStringList LanguageSwitcher::languages()
{
    return {QStringLiteral("en"), QStringLiteral("zh_CN"), QStringLiteral("zh_TW")};
}

QString LanguageSwitcher::normalize(const QString &name)
{
    QString n = name.trimmed();
    n.replace(QLatin1Char('-'), QLatin1Char('_'));
    const QString lower = n.toLower();
    if (lower == QLatin1String("en") || lower.startsWith(QLatin1String("en_")) || lower == QLatin1String("c"))
        return QStringLiteral("en");
    if (lower == QLatin1String("zh_tw") || lower == QLatin1String("zh_hk") || lower == QLatin1String("zh_mo")
        || lower.startsWith(QLatin1String("zh_hant")))
        return QStringLiteral("zh_TW");
    if (lower == QLatin1String("zh") || lower == QLatin1String("zh_cn") || lower == QLatin1String("zh_sg")
        || lower.startsWith(QLatin1String("zh_hans")))
        return QStringLiteral("zh_CN");
    return QString();
}

QString LanguageSwitcher::fromLocale(const QLocale &locale)
{
    if (locale.language() != QLocale::Chinese)
        return QStringLiteral("en");
    const auto territory = locale.territory();
    if (locale.script() == QLocale::TraditionalChineseScript || territory == QLocale::Taiwan
        || territory == QLocale::HongKong || territory == QLocale::Macao)
        return QStringLiteral("zh_TW");
    return QStringLiteral("zh_CN");
}

bool LanguageSwitcher::setLanguage(const QString &language, const QString &qmDir, QString *error)
{
    const QString lang = normalize(language);
    if (lang.isEmpty()) {
        if (error)
            *error = tr("Unknown language \"%1\"; choose one of: %2.").arg(language, languages().join(QStringLiteral(", ")));
        return false;
    }
    if (lang == QLatin1String("en")) {
        // The source texts are English; imudesk_en holds only the plural forms.
        uninstall();
        if (m_app.load(QStringLiteral("imudesk_en"), qmDir))
            m_appInstalled = QCoreApplication::installTranslator(&m_app);
        m_language = lang;
        applyFont(lang);
        return true;
    }
    QTranslator app;
    if (!app.load(QStringLiteral("imudesk_") + lang, qmDir)) {
        if (error)
            *error = tr("The %1 translation was not found in %2.").arg(lang, qmDir);
        return false;
    }
    uninstall();
    if (!m_app.load(QStringLiteral("imudesk_") + lang, qmDir))
        return false;
    // Qt's own strings (standard buttons, context menus) when the distribution ships them.
    const bool haveQt = m_qt.load(QStringLiteral("qtbase_") + lang, QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    if (haveQt)
        m_qtInstalled = QCoreApplication::installTranslator(&m_qt);
    m_appInstalled = QCoreApplication::installTranslator(&m_app);
    m_language = lang;
    applyFont(lang);
    return true;
}

QString LanguageSwitcher::cjkFamily(const QString &language)
{
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return QString();
    const QString lang = normalize(language);
    QStringList candidates;
    if (lang == QLatin1String("zh_CN"))
        candidates = {QStringLiteral("Noto Sans CJK SC"), QStringLiteral("Source Han Sans SC"),
                      QStringLiteral("WenQuanYi Micro Hei"), QStringLiteral("Droid Sans Fallback")};
    else if (lang == QLatin1String("zh_TW"))
        candidates = {QStringLiteral("Noto Sans CJK TC"), QStringLiteral("Source Han Sans TC"),
                      QStringLiteral("AR PL UMing TW"), QStringLiteral("Droid Sans Fallback")};
    const QStringList installed = QFontDatabase::families();
    for (const QString &family : candidates)
        if (installed.contains(family))
            return family;
    return QString();
}

void LanguageSwitcher::applyFont(const QString &lang)
{
    if (!qobject_cast<QGuiApplication *>(QCoreApplication::instance()))
        return;
    if (!m_haveBaseFont) {
        m_baseFont = QGuiApplication::font();
        m_haveBaseFont = true;
    }
    QFont font = m_baseFont;
    const QString cjk = cjkFamily(lang);
    if (!cjk.isEmpty())
        font.setFamilies({cjk, m_baseFont.family()});
    if (font != QGuiApplication::font())
        QApplication::setFont(font);
}

void LanguageSwitcher::uninstall()
{
    if (m_appInstalled)
        QCoreApplication::removeTranslator(&m_app);
    if (m_qtInstalled)
        QCoreApplication::removeTranslator(&m_qt);
    m_appInstalled = m_qtInstalled = false;
}

} // namespace imudesk::ui
