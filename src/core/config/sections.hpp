#pragma once
// Every tunable of dynanav, with its default and a one-line doc (STYLE.md habit 4): one header
// per module section. Each struct's visit() lists its fields once; the YAML loader, the
// unknown-key check and the echo of the effective config (config_used.yaml) all come from it.
#include "core/config/assist.hpp"
#include "core/config/audio.hpp"
#include "core/config/dynamics.hpp"
#include "core/config/io.hpp"
#include "core/config/loop.hpp"
#include "core/config/mapping.hpp"
#include "core/config/objects.hpp"
#include "core/config/orb.hpp"
#include "core/config/outputs.hpp"
#include "core/config/perception.hpp"
#include "core/config/run.hpp"
#include "core/config/tracking.hpp"
