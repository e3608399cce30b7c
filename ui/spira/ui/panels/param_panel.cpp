#include "spira/ui/panels/param_panel.h"

#include <algorithm>
#include <vector>

#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "spira/ui/panels/param_field.h"

namespace spira::ui {

ParamPanel::ParamPanel(std::string section, const ParamSchema& schema, QWidget* parent)
    : QWidget(parent), section_(std::move(section)), schema_(schema)
{
  setObjectName(QString::fromStdString("params_" + section_));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);

  // Categories in the order the schema first names them.
  std::vector<std::string> categories;
  for (const ParamDef& d : schema_.defs())
    if (std::find(categories.begin(), categories.end(), d.category) == categories.end())
      categories.push_back(d.category);
  for (const std::string& category : categories) {
    auto* box = new QGroupBox(category.empty() ? tr("General") : QString::fromStdString(category), this);
    auto* form = new QFormLayout(box);
    form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form->setLabelAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    for (const ParamDef& d : schema_.defs()) {
      if (d.category != category) continue;
      auto* label = new QLabel(QString::fromStdString(d.label), box);
      label->setToolTip(QStringLiteral("<p><b>%1</b> (%2)</p><p>%3</p>")
                            .arg(QString::fromStdString(d.label).toHtmlEscaped(),
                                 QString::fromStdString(d.key).toHtmlEscaped(),
                                 QString::fromStdString(d.tooltip).toHtmlEscaped()));
      auto* field = new ParamField(d, box);
      label->setBuddy(field->editor());
      form->addRow(label, field);
      fields_[d.key] = field;
      labels_[d.key] = label;
      const std::string key = d.key;
      connect(field, &ParamField::edited, this, [this, key](const ParamValue& v) {
        // Line edits report every loss of focus; only a different value is an edit.
        if (v == shown_[key]) return;
        emit valueEdited(section_, key, v);
      });
      connect(field, &ParamField::resetRequested, this,
              [this, key] { emit keyResetRequested(section_, key); });
    }
    layout->addWidget(box);
  }

  resetAll_ = new QPushButton(tr("Reset All to Defaults"), this);
  resetAll_->setObjectName(QStringLiteral("resetAll"));
  resetAll_->setToolTip(tr("Set every parameter of this section back to its default"));
  resetAll_->setEnabled(false);
  connect(resetAll_, &QPushButton::clicked, this, [this] { emit sectionResetRequested(section_); });
  auto* row = new QHBoxLayout;
  row->addStretch(1);
  row->addWidget(resetAll_);
  layout->addLayout(row);
  layout->addStretch(1);
}

void ParamPanel::setStored(const ParamSet& stored)
{
  bool anyChanged = false;
  for (const ParamDef& d : schema_.defs()) {
    const bool set = stored.has(d.key) && stored.values().at(d.key) != d.defaultValue;
    const ParamValue& v = set ? stored.values().at(d.key) : d.defaultValue;
    fields_.at(d.key)->setValue(v, !set);
    shown_[d.key] = v;
    QLabel* label = labels_.at(d.key);
    QFont f = label->font();
    f.setBold(set);
    label->setFont(f);
    anyChanged = anyChanged || set;
  }
  resetAll_->setEnabled(anyChanged);
}

ParamField* ParamPanel::field(const std::string& key) const
{
  auto it = fields_.find(key);
  return it == fields_.end() ? nullptr : it->second;
}

QLabel* ParamPanel::label(const std::string& key) const
{
  auto it = labels_.find(key);
  return it == labels_.end() ? nullptr : it->second;
}

}  // namespace spira::ui
