#include "analysis/gradient_form.hpp"

#include "support/error.hpp"

namespace sphkern {

GradientForm parse_gradient_form(const std::string& text)
{
    if (text == "sum") return GradientForm::sum;
    if (text == "difference") return GradientForm::difference;
    if (text == "monaghan") return GradientForm::monaghan;
    fail_unknown("gradient form \"" + text + "\" is unknown, expected sum, difference or monaghan");
}

const char* gradient_form_name(GradientForm form)
{
    return form == GradientForm::sum ? "sum" : form == GradientForm::difference ? "difference" : "monaghan";
}

} // namespace sphkern
