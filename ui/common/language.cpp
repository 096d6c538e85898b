#include "ui/common/language.h"

#include <QCoreApplication>
#include <QEvent>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>
#include <memory>

namespace probecycle::ui {

namespace {

struct Installed {
    std::unique_ptr<QTranslator> app;
    std::unique_ptr<QTranslator> qt;  // Qt's own dialogs and context menus
    QString code{QStringLiteral("en")};
};

Installed& installed() {
    static Installed state;
    return state;
}

// Watches its parent for LanguageChange and runs the text's builder again.
class Retranslator : public QObject {
  public:
    explicit Retranslator(QObject* target) : QObject(target) { target->installEventFilter(this); }
    void set(std::function<void()> apply) {
        apply_ = std::move(apply);
        if (apply_) apply_();
    }
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == parent() && event->type() == QEvent::LanguageChange && apply_) apply_();
        return false;
    }

  private:
    std::function<void()> apply_;
};

QString language_for_locale(const QLocale& locale) {
    if (locale.language() == QLocale::Chinese) return QStringLiteral("zh_CN");
    if (locale.language() == QLocale::Russian) return QStringLiteral("ru");
    return QStringLiteral("en");
}

}  // namespace

QStringList available_languages() {
    return {QStringLiteral("en"), QStringLiteral("zh_CN"), QStringLiteral("ru")};
}

QString native_language_name(const QString& code) {
    if (code == QLatin1String("zh_CN")) return QStringLiteral("中文 (简体)");
    if (code == QLatin1String("ru")) return QStringLiteral("Русский");
    return QStringLiteral("English");
}

QString apply_language(const QString& code) {
    const QString wanted = code.isEmpty() ? language_for_locale(QLocale::system()) : code;
    Installed& state = installed();
    if (state.app) QCoreApplication::removeTranslator(state.app.get());
    if (state.qt) QCoreApplication::removeTranslator(state.qt.get());
    state.app.reset();
    state.qt.reset();
    state.code = QStringLiteral("en");
    if (wanted != QLatin1String("en")) {
        auto app = std::make_unique<QTranslator>();
        if (app->load(QStringLiteral(":/i18n/probecycle_") + wanted + QStringLiteral(".qm"))) {
            QCoreApplication::installTranslator(app.get());
            state.app = std::move(app);
            state.code = wanted;
            auto qt = std::make_unique<QTranslator>();
            if (qt->load(QStringLiteral("qtbase_") + wanted,
                         QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
                QCoreApplication::installTranslator(qt.get());
                state.qt = std::move(qt);
            }
        }
    }
    // Numbers follow the interface language (decimal comma in Russian).
    QLocale::setDefault(state.code == QLatin1String("en") ? QLocale(QLocale::English)
                                                          : QLocale(state.code));
    return state.code;
}

QString current_language() {
    return installed().code;
}

void keep_translated(QObject* target, std::function<void()> apply) {
    Retranslator* retranslator = nullptr;
    for (QObject* child : target->children()) {
        if (auto* found = dynamic_cast<Retranslator*>(child)) retranslator = found;
    }
    if (retranslator == nullptr) retranslator = new Retranslator(target);
    retranslator->set(std::move(apply));
}

}  // namespace probecycle::ui
