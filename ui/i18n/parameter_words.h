#pragma once
// The words of sim/'s parameter table (sim/world/parameters.cpp) that the
// workbench shows: the rows' labels and their help (tooltips). sim/ holds no Qt, so its English words
// are listed here for lupdate (QT_TRANSLATE_NOOP) and shown through
// parameterLabel(); test_translations fails when a label of the table is
// missing from the list, so a new parameter cannot slip in untranslated.
#include "sim/world/parameters.h"

#include <QString>
#include <QStringList>

namespace forcelab {

/// `p`'s label in the current language ("Drag k" → "Luftwiderstand k").
QString parameterLabel(const sim::Parameter& p);
/// Every label the list holds, in English (for the test).
QStringList listedParameterLabels();
/// `p`'s help, its tooltip, in the current language.
QString parameterHelp(const sim::Parameter& p);
/// Every help the list holds, in English (for the test).
QStringList listedParameterHelp();

} // namespace forcelab
