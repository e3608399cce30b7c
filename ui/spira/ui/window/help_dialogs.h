#pragma once

#include <QString>

class QDialog;
class QMainWindow;
class QWidget;

namespace spira::ui {

// The About box's text (HTML): version, what Spira does, the libraries it was built with and
// their versions, and the licences of the bundled robot descriptions.
QString aboutText();
// The About box, modal.
void showAboutDialog(QWidget* parent);

// Every command of `window`'s menus (submenus included) that has a keyboard shortcut, as an HTML
// table (command, keys).
QString shortcutsText(QMainWindow* window);
// A non-modal window listing the shortcuts; it is a child of `window` and deletes itself when closed.
QDialog* showShortcutsDialog(QMainWindow* window);

}  // namespace spira::ui
