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
  catch (const nlohmann::json::out_of_range& e)
  {
    // KNOWN: E1 (Testing/Fuzz/README.md). Parser::Read catches only json::parse_error, but
    // nlohmann throws out_of_range.406 for a number beyond the double range ("time": 1e400), so
    // it escapes as no InputError and ends lct-render through std::terminate (lct-render's main
    // catches RenderKeys::InputError only).
    if (lct_fuzz::Known("E1", e.id == 406))
    {
      return 0;
    }
    LCT_FUZZ_CHECK(false, "the JSON reader threw something other than InputError: " << e.what());
  }
  catch (const std::exception& e)
  {
    LCT_FUZZ_CHECK(false, "the JSON reader threw something other than InputError: " << e.what());
  }
  lct_fuzz::RenderKeysLikeLctRender(keys);
  return 0;
}
