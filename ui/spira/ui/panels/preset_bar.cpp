#include "spira/ui/panels/preset_bar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QToolButton>

#include "spira/base/error.h"

namespace spira::ui {

PresetBar::PresetBar(Document& doc, PresetStore store, QWidget* parent)
    : QWidget(parent), doc_(doc), store_(std::move(store))
{
  setObjectName(QStringLiteral("presetBar"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* label = new QLabel(tr("Preset"), this);
  combo_ = new QComboBox(this);
  combo_->setObjectName(QStringLiteral("presetCombo"));
  combo_->setToolTip(
      tr("Your saved plan settings: choosing one replaces every plan setting (undo with Ctrl+Z)"));
  combo_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  label->setBuddy(combo_);
  save_ = new QToolButton(this);
  save_->setText(tr("Save..."));
  save_->setToolTip(tr("Save the current plan settings as a preset of yours"));
  delete_ = new QToolButton(this);
  delete_->setText(tr("Delete"));
  delete_->setToolTip(tr("Delete the chosen preset"));
  layout->addWidget(label);
  layout->addWidget(combo_, 1);
  layout->addWidget(save_);
  layout->addWidget(delete_);

  connect(combo_, QOverload<int>::of(&QComboBox::activated), this, [this](int i) {
    if (i <= 0) return;  // the "choose" prompt
    const QString name = combo_->itemText(i);
    guarded([&] { apply(name); });
  });
  connect(save_, &QToolButton::clicked, this, &PresetBar::askAndSave);
  connect(delete_, &QToolButton::clicked, this, &PresetBar::askAndRemove);
  reload();
}

template <class Fn>
void PresetBar::guarded(Fn&& fn)
{
  try {
    fn();
  } catch (const Error& e) {
    emit failed(QString::fromUtf8(e.what()), QString::fromStdString(e.hint()));
  }
}

void PresetBar::reload()
{
  const QString current = combo_->currentIndex() > 0 ? combo_->currentText() : QString();
  combo_->clear();
  const QStringList names = store_.names();
  combo_->addItem(names.isEmpty() ? tr("(no presets yet)") : tr("(choose a preset)"));
  combo_->addItems(names);
  const int i = combo_->findText(current);
  combo_->setCurrentIndex(i > 0 ? i : 0);
  delete_->setEnabled(!names.isEmpty());
}

void PresetBar::saveCurrentAs(const QString& name)
{
  store_.save(name, *doc_.settings());
  reload();
  combo_->setCurrentIndex(combo_->findText(name.trimmed()));
}

void PresetBar::apply(const QString& name)
{
  PlanSettings settings = store_.load(name);
  // One undo step named for the preset; applying the same values again makes no step.
  doc_.setPlanSettings(std::move(settings), tr("Apply preset %1").arg(name.trimmed()).toStdString());
  combo_->setCurrentIndex(std::max(0, combo_->findText(name.trimmed())));
}

void PresetBar::remove(const QString& name)
{
  store_.remove(name);
  reload();
}

void PresetBar::askAndSave()
{
  bool ok = false;
  const QString suggested = combo_->currentIndex() > 0 ? combo_->currentText() : QString();
  const QString name =
      QInputDialog::getText(this, tr("Save Preset"), tr("Preset name:"), QLineEdit::Normal, suggested, &ok);
  if (!ok || name.trimmed().isEmpty()) return;
  if (store_.contains(name) &&
      QMessageBox::question(this, tr("Save Preset"), tr("Replace the preset \"%1\"?").arg(name.trimmed())) !=
          QMessageBox::Yes)
    return;
  guarded([&] { saveCurrentAs(name); });
}

void PresetBar::askAndRemove()
{
  if (combo_->currentIndex() <= 0) return;
  const QString name = combo_->currentText();
  if (QMessageBox::question(this, tr("Delete Preset"), tr("Delete the preset \"%1\"?").arg(name)) !=
      QMessageBox::Yes)
    return;
  remove(name);
}

}  // namespace spira::ui
