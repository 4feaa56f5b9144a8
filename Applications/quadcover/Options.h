// Options.h: the command line's options. Every stage option is a filter property under its own
// name in kebab case (SmoothingWeight: --smoothing-weight), its range and default the filter's;
// a switch takes --name and --no-name.
#ifndef quadcover_app_Options_h
#define quadcover_app_Options_h

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace quadcover_app
{
class Pipeline;

/// One stage option, bound to the filter property (or properties) it sets.
struct Option
{
  enum class Kind
  {
    Number, ///< a real number in [low, high]
    Whole,  ///< a whole number in [low, high]
    Switch, ///< on or off
    Choice  ///< one of `choices` (the property takes its index)
  };
  std::string stage;    ///< the stage it belongs to (--stage's names)
  std::string property; ///< the filter property, e.g. SmoothingWeight
  std::string flag;     ///< e.g. smoothing-weight (without the dashes)
  std::string meaning;
  Kind kind = Kind::Number;
  double low = 0.0;
  double high = 0.0;
  std::vector<std::string> choices;
  /// --help's default where the command line sets one of its own (otherwise the filter's)
  std::string defaultText;
  std::function<double()> get;
  std::function<void(double)> set;

  /// The value as the command line spells it (2, 0.95, on, greedy).
  std::string Text(double value) const;
};

/// The properties of every stage of `pipeline`, in stage order.
std::vector<Option> StageOptions(Pipeline& pipeline);

/// What the command line asks for besides the stage options.
struct Request
{
  std::string input;
  std::string output;
  std::string stage = "quads";
  std::string stats;
  bool verbose = false;
  bool help = false;
  std::vector<std::string> given; ///< the stage options given, by flag (without the dashes)
};

/**
 * Reads the arguments into `request` and sets the options it names on their filters.
 * @return "" or what is wrong with the arguments (one line)
 */
std::string Parse(int argc, char* argv[], const std::vector<Option>& options, Request& request);

/// The --help text, with every option's range and default (the filters' current values).
void PrintUsage(std::ostream& os, const std::vector<Option>& options);
}

#endif
