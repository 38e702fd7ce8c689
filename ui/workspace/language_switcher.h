#pragma once
// Installs ImuDesk's translation for one language (English is the source language)
// and switches it at run time; widgets retranslate on QEvent::LanguageChange.
#include <QFont>
#include <QLocale>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTranslator>

namespace imudesk::ui {

class LanguageSwitcher : public QObject {
    Q_OBJECT
public:
    // Where the build embeds the .qm files (app/gui/CMakeLists.txt).
    static constexpr const char *kResourceDir = ":/i18n";

    explicit LanguageSwitcher(QObject *parent = nullptr);
    ~LanguageSwitcher() override;

    // "en", "zh_CN", "zh_TW".
    static QStringList languages();
    // Maps spellings such as "zh-CN", "zh_Hans", "zh_HK", "en_US" to one of languages(); "" if none fits.
    static QString normalize(const QString &name);
    // The language for a locale: Chinese in Traditional script or from TW/HK/MO -> zh_TW, other
    // Chinese -> zh_CN, anything else -> en.
    static QString fromLocale(const QLocale &locale);

    // Loads imudesk_<lang>.qm from `qmDir` (and Qt's own qtbase_<lang>.qm when installed)
    // and installs it in place of the previous one. "en" removes the translation.
    bool setLanguage(const QString &language, const QString &qmDir = QString::fromLatin1(kResourceDir),
                     QString *error = nullptr);
    QString language() const { return m_language; }

    // The installed CJK font family for a Chinese language (Noto Sans CJK SC or TC, or
    // another Simplified or Traditional face); "" for English or when none is installed.
    static QString cjkFamily(const QString &language);

private:
    void uninstall();
    // The application font for `lang`: the CJK family first where one is installed, so that
    // Chinese text uses the glyphs of its own script rather than whatever fontconfig picks.
    void applyFont(const QString &lang);

    QFont m_baseFont;
    bool m_haveBaseFont = false;
    QTranslator m_app;
    QTranslator m_qt;
    bool m_appInstalled = false;
    bool m_qtInstalled = false;
    QString m_language = QStringLiteral("en");
};

} // namespace imudesk::ui
