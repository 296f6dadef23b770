// Fuzz target: the ParaView state file reader of lct-render (RenderKeys::ReadPvsm in
// Examples/RenderKeys.h) on arbitrary bytes. ReadPvsm takes a file name, so each input is written
// to a temporary file first. The camera track it returns becomes the camera keys, as
// `lct-render state.pvsm` does, and the keys are then used as lct-render uses them
// (FuzzRenderKeys.h). Seeds: Testing/Data/Render/*.pvsm; dictionary: FuzzRenderKeysPvsm.dict.
//
// Properties: no crash, sanitizer report or hang; ReadPvsm returns a track of at least 2 keys in
// increasing, finite time with linear or spline interpolation, or throws RenderKeys::InputError
// and nothing else; accepted keys render.
#include "FuzzInput.h"
#include "FuzzRenderKeys.h"

#include <cmath>
#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  lct_fuzz::SilenceStdErr();
  const std::string& file = lct_fuzz::InputAsFile("lct-fuzz-pvsm", data, size);
  RenderKeys::StateCamera state;
  try
  {
    state = RenderKeys::ReadPvsm(file);
  }
  catch (const RenderKeys::InputError&)
  {
    return 0;
  }
  catch (const std::exception& e)
  {
    LCT_FUZZ_CHECK(false, "ReadPvsm threw something other than InputError: " << e.what());
  }
  LCT_FUZZ_CHECK(state.Interpolation == "linear" || state.Interpolation == "spline",
    "ReadPvsm returned interpolation \"" << state.Interpolation << "\"");
  LCT_FUZZ_CHECK(std::isfinite(state.Start) && std::isfinite(state.End) && state.End > state.Start,
    "ReadPvsm returned the scene times " << state.Start << ".." << state.End);
  for (size_t i = 1; i < state.Keys.size(); ++i)
  {
    LCT_FUZZ_CHECK(state.Keys[i - 1].Time < state.Keys[i].Time, "key times not increasing");
  }
  RenderKeys::Keys keys;
  keys.Source = file;
  keys.Camera = state.Keys;
  keys.Interpolation = state.Interpolation;
  lct_fuzz::RenderKeysLikeLctRender(keys);
  return 0;
}
