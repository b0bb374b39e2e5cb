// The HTML pages of `raygrade serve`: what a refusal, a student, an instructor and the deep
// linking picker see. Layout only: every value comes from the caller.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace raygrade::serve {

// A whole page: title, and body markup already escaped.
std::string page(const std::string& title, const std::string& body);

// The page of a refusal: the status and why.
std::string refusal_page(int status, const std::string& reason);

// The JSON script element the pages carry (id "raygrade-launch"), safe inside <script>.
std::string launch_script(const nlohmann::json& launch);

// The student's page: the handout page of their numbers, with the launch's JSON and a submit
// button that posts the handout's answers to the tool and shows the feedback returned.
std::string student_page(const std::string& handout_html, const nlohmann::json& launch);

struct PickerItem {
  std::string name;  // the assignment's file name
  std::string title;
  double points = 0;
};
// The deep linking picker: one form per assignment posting to `deep_link_url`.
std::string picker_page(const std::vector<PickerItem>& items, const std::string& deep_link_url,
                        const std::string& launch_id, const std::string& csrf);

// The page that posts the signed deep linking response back to the platform.
std::string deep_link_return_page(const std::string& return_url, const std::string& jwt);

// The instructor's page: links to the report and the gradebook, the regrade form.
std::string instructor_page(const std::string& title, const std::string& public_url,
                            const nlohmann::json& launch, int submissions);

// The end of a dynamic registration: tells the platform's window to close the tool's.
std::string registration_done_page(const std::string& issuer, const std::string& client_id);

}  // namespace raygrade::serve
