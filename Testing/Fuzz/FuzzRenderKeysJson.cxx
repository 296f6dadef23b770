// Fuzz target: the keyframe JSON reader of lct-render (RenderKeys::Parser::Read in
// Examples/RenderKeys.h) on arbitrary bytes, then the keys it returns as lct-render uses them
// (FuzzRenderKeys.h). Seeds: Testing/Data/Render/*.json; dictionary: FuzzRenderKeysJson.dict.
//
// Properties: no crash, sanitizer report or hang; the reader either returns keys or throws
// RenderKeys::InputError (anything else escaping, e.g. a nlohmann::json exception, would end
// lct-render with std::terminate); accepted keys keep the reader's promises and render.
#include "FuzzInput.h"
#include "FuzzRenderKeys.h"

#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  lct_fuzz::SilenceStdErr();
  const std::string text(reinterpret_cast<const char*>(data), size);
  RenderKeys::Keys keys;
  try
  {
    keys = RenderKeys::Parser("fuzz.json").Read(text);
  }
  catch (const RenderKeys::InputError&)
  {
    return 0; // a clean, named input error
  }
  catch (const std::exception& e)
  {
    LCT_FUZZ_CHECK(false, "the JSON reader threw something other than InputError: " << e.what());
  }
  lct_fuzz::RenderKeysLikeLctRender(keys);
  return 0;
}
