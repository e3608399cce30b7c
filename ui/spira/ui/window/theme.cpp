#include "spira/ui/window/theme.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QMenu>
#include <QPalette>
#include <QSettings>
#include <QStyle>
#include <QStyleFactory>

#include <vtkRenderer.h>

namespace spira::ui {

namespace {

constexpr const char* kThemeKey = "view/theme";

struct Original {
  QString style;
  QPalette palette;
};

// What the application looked like before any theme was applied: the "System" theme.
Original& original()
{
  static Original o{qApp->style()->objectName(), QApplication::palette()};
  return o;
}

Theme& current()
{
  static Theme t = Theme::System;
  return t;
}

QPalette darkPalette()
{
  const QColor window(45, 47, 51), base(32, 34, 37), text(230, 232, 235), disabled(130, 134, 140);
  const QColor highlight(58, 130, 218);
  QPalette p;
  p.setColor(QPalette::Window, window);
  p.setColor(QPalette::WindowText, text);
  p.setColor(QPalette::Base, base);
  p.setColor(QPalette::AlternateBase, QColor(52, 55, 60));
  p.setColor(QPalette::ToolTipBase, QColor(60, 63, 68));
  p.setColor(QPalette::ToolTipText, text);
  p.setColor(QPalette::PlaceholderText, disabled);
  p.setColor(QPalette::Text, text);
  p.setColor(QPalette::Button, QColor(55, 58, 63));
  p.setColor(QPalette::ButtonText, text);
  p.setColor(QPalette::BrightText, QColor(255, 110, 110));
  p.setColor(QPalette::Link, QColor(110, 170, 240));
  p.setColor(QPalette::LinkVisited, QColor(170, 140, 230));
  p.setColor(QPalette::Highlight, highlight);
  p.setColor(QPalette::HighlightedText, Qt::white);
  // Secondary text ("color: palette(mid)") must stay readable on the dark window.
  p.setColor(QPalette::Light, QColor(75, 78, 84));
  p.setColor(QPalette::Midlight, QColor(62, 65, 70));
  p.setColor(QPalette::Mid, QColor(150, 155, 162));
  p.setColor(QPalette::Dark, QColor(25, 26, 28));
  p.setColor(QPalette::Shadow, QColor(15, 15, 16));
  for (auto role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::HighlightedText})
    p.setColor(QPalette::Disabled, role, disabled);
  p.setColor(QPalette::Disabled, QPalette::Highlight, QColor(80, 84, 90));
  return p;
}

}  // namespace

QString themeKey(Theme t)
{
  switch (t) {
    case Theme::Light:
      return QStringLiteral("light");
    case Theme::Dark:
      return QStringLiteral("dark");
    case Theme::System:
      break;
  }
  return QStringLiteral("system");
}

Theme themeFromKey(const QString& key)
{
  if (key == QLatin1String("light")) return Theme::Light;
  if (key == QLatin1String("dark")) return Theme::Dark;
  return Theme::System;
}

QString themeLabel(Theme t)
{
  switch (t) {
    case Theme::Light:
      return QObject::tr("&Light");
    case Theme::Dark:
      return QObject::tr("&Dark");
    case Theme::System:
      break;
  }
  return QObject::tr("&System");
}

void applyTheme(Theme t)
{
  const Original& o = original();
  if (t == Theme::System) {
    if (QStyle* s = QStyleFactory::create(o.style)) QApplication::setStyle(s);
    QApplication::setPalette(o.palette);
  } else {
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QApplication::setPalette(t == Theme::Dark ? darkPalette() : QApplication::style()->standardPalette());
  }
  current() = t;
}

Theme currentTheme()
{
  return current();
}

Theme savedTheme()
{
  return themeFromKey(QSettings().value(kThemeKey).toString());
}

void saveTheme(Theme t)
{
  QSettings().setValue(kThemeKey, themeKey(t));
}

bool paletteIsDark()
{
  return QApplication::palette().color(QPalette::Window).lightness() < 128;
}

void applySceneBackground(vtkRenderer* renderer)
{
  if (!renderer) return;
  renderer->GradientBackgroundOn();
  if (paletteIsDark()) {
    renderer->SetBackground(0.50, 0.55, 0.61);
    renderer->SetBackground2(0.76, 0.79, 0.83);
  } else {
    renderer->SetBackground(0.70, 0.75, 0.81);
    renderer->SetBackground2(0.93, 0.95, 0.97);
  }
}

QActionGroup* addThemeMenu(QMenu* menu, QObject* owner, std::function<void()> changed)
{
  original();  // remember the system look before anything changes it
  QMenu* sub = menu->addMenu(QObject::tr("T&heme"));
  sub->setObjectName(QStringLiteral("themeMenu"));
  auto* group = new QActionGroup(owner);
  group->setExclusive(true);
  const Theme saved = savedTheme();
  for (Theme t : {Theme::System, Theme::Light, Theme::Dark}) {
    QAction* a = sub->addAction(themeLabel(t));
    a->setObjectName(QStringLiteral("theme_") + themeKey(t));
    a->setCheckable(true);
    a->setChecked(t == saved);
    a->setData(themeKey(t));
    group->addAction(a);
    QObject::connect(a, &QAction::triggered, owner, [t, changed] {
      applyTheme(t);
      saveTheme(t);
      if (changed) changed();
    });
  }
  return group;
}

}  // namespace spira::ui
