#pragma once
#include "fixture_high/high.h"  // up: what the test must catch
