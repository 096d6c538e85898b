#pragma once

// The interface language: English (the source text), Chinese (zh_CN) or
// Russian, from the system locale or the user's choice. Translations are
// embedded in the program as resources.

#include <QString>
#include <QStringList>

namespace probecycle::ui {

// Language codes offered in the View menu.
QStringList available_languages();
// The language's own name ("中文", "Русский").
QString native_language_name(const QString& code);
// Installs the translation for `code` ("" = follow the system locale) and
// returns the language in effect. Widgets get a LanguageChange event.
QString apply_language(const QString& code);
// The language in effect ("en", "zh_CN", "ru").
QString current_language();

}  // namespace probecycle::ui
