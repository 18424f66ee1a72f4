#pragma once
// The station's answer to the service manager: SIGTERM and SIGINT ask it to
// finish the current frame, finalize its outputs and release its cameras;
// SIGHUP asks it to reload its config at the next frame boundary. Handlers
// only set flags; the frame loop polls them.
//
//   installShutdownSignals();
//   while (!stopRequested()) {
//       if (takeReloadRequest()) reload();
//       station.frame();
//   }

namespace arcomp {

void installShutdownSignals();
bool stopRequested();
// True once per SIGHUP received (several before one poll count as one).
bool takeReloadRequest();
// For the window's quit key and for tests.
void requestStop();
void requestReload();

}  // namespace arcomp
