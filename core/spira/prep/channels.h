#pragma once

#include <string>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

// The scalar process channels of a trajectory by name, so deadband, lead and reports treat the
// built-in ones and the `extra` ones alike. Built-in names: "height" (mm), "travelSpeed" (mm/s),
// "wireFeed" (mm/s).
extern const char* const kHeightChannel;
extern const char* const kTravelSpeedChannel;
extern const char* const kWireFeedChannel;

// The three built-in names followed by the extra channels in map order.
std::vector<std::string> scalarChannelNames(const Trajectory& trajectory);

// One value per point. Throws InputError for an unknown name or an extra channel whose size is not
// the point count.
std::vector<double> channelValues(const Trajectory& trajectory, const std::string& name);

// Writes one value per point into the named channel (an unknown name becomes an extra channel).
void setChannelValues(Trajectory& trajectory, const std::string& name, const std::vector<double>& values);

// Throws InputError when an extra channel does not hold one value per point.
void checkExtraChannels(const Trajectory& trajectory);

}  // namespace spira
