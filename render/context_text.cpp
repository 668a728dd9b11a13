#include "render/context_text.h"

#include <vtkContext2D.h>
#include <vtkObjectFactory.h>
#include <vtkStdString.h>

namespace sedem::render {

vtkStandardNewMacro(ContextText);

void ContextText::Set(const std::string& text, float x, float y, int size, bool bold) {
  text_ = text;
  x_ = x;
  y_ = y;
  prop_->SetFontFamilyToArial();
  prop_->SetFontSize(size);
  prop_->SetBold(bold);
  prop_->SetColor(0, 0, 0);
  prop_->SetJustificationToCentered();
  prop_->SetVerticalJustificationToCentered();
}

bool ContextText::Paint(vtkContext2D* painter) {
  if (text_.empty()) return true;
  painter->ApplyTextProp(prop_);
  painter->DrawString(x_, y_, vtkStdString(text_));
  return true;
}

}  // namespace sedem::render
