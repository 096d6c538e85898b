#pragma once

// The interface language: English (the source text), Chinese (zh_CN) or
// Russian, from the system locale or the user's choice. Translations are
// embedded in the program as resources.

#include <QString>
#include <QStringList>
#include <functional>

class QObject;

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

// For a text built at run time (a status, an error, a result in words), which
// a widget's own retranslate() does not know: runs `apply` now and again
// whenever `target` gets a LanguageChange event, so the text is rebuilt in
// the new language. A later call for the same target replaces the earlier.
void keep_translated(QObject* target, std::function<void()> apply);

}  // namespace probecycle::ui
