#include "spira/prep/channels.h"

#include "spira/base/error.h"

namespace spira {

const char* const kHeightChannel = "height";
const char* const kTravelSpeedChannel = "travelSpeed";
const char* const kWireFeedChannel = "wireFeed";

namespace {

double TrajectoryPoint::*builtIn(const std::string& name)
{
  if (name == kHeightChannel) return &TrajectoryPoint::height;
  if (name == kTravelSpeedChannel) return &TrajectoryPoint::travelSpeed;
  if (name == kWireFeedChannel) return &TrajectoryPoint::wireFeed;
  return nullptr;
}

}  // namespace

std::vector<std::string> scalarChannelNames(const Trajectory& trajectory)
{
  std::vector<std::string> names{kHeightChannel, kTravelSpeedChannel, kWireFeedChannel};
  for (const auto& [name, values] : trajectory.extra) names.push_back(name);
  return names;
}

void checkExtraChannels(const Trajectory& trajectory)
{
  for (const auto& [name, values] : trajectory.extra) {
    if (values.size() != trajectory.size()) {
      throw InputError("trajectory channel '" + name + "' has " + std::to_string(values.size()) +
                           " values for " + std::to_string(trajectory.size()) + " points",
                       "give every extra channel one value per trajectory point");
    }
  }
}

std::vector<double> channelValues(const Trajectory& trajectory, const std::string& name)
{
  if (auto member = builtIn(name)) {
    std::vector<double> values;
    values.reserve(trajectory.size());
    for (const TrajectoryPoint& p : trajectory.points) values.push_back(p.*member);
    return values;
  }
  const auto it = trajectory.extra.find(name);
  if (it == trajectory.extra.end()) {
    throw InputError("the trajectory has no channel '" + name + "'",
                     "use height, travelSpeed, wireFeed or one of the trajectory's extra channels");
  }
  if (it->second.size() != trajectory.size()) checkExtraChannels(trajectory);
  return it->second;
}

void setChannelValues(Trajectory& trajectory, const std::string& name, const std::vector<double>& values)
{
  if (values.size() != trajectory.size()) {
    throw InputError("channel '" + name + "' gets " + std::to_string(values.size()) + " values for " +
                         std::to_string(trajectory.size()) + " points",
                     "pass one value per trajectory point");
  }
  if (auto member = builtIn(name)) {
    for (size_t i = 0; i < values.size(); ++i) trajectory.points[i].*member = values[i];
    return;
  }
  trajectory.extra[name] = values;
}

}  // namespace spira
