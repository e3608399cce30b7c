#pragma once

#include <QTreeWidget>

namespace spira {
class Document;
struct MeshReport;
}  // namespace spira

namespace spira::ui {

// The document's objects as a two-column tree (object, value): Part, Substrate, Cell, Plan
// settings and Results. It is rebuilt from the Document on every change notification and holds
// nothing the Document does not; expansion is kept across rebuilds.
class DocumentTree : public QTreeWidget {
  Q_OBJECT

 public:
  explicit DocumentTree(QWidget* parent = nullptr);

  // `partReport` is the validation report of the document's part mesh (null when unknown).
  void refresh(const Document& doc, const MeshReport* partReport);

  // The top-level item for "Part", "Substrate", "Cell", "Plan settings" or "Results".
  QTreeWidgetItem* section(const QString& title) const;
};

}  // namespace spira::ui
